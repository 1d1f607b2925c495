// atomic_file.h: write an output file all at once (temp file in the same folder, then
// rename), so a reader never sees half a file and a failed run leaves none behind.
#pragma once

#include <string>

namespace pamsim {

// Writes `content` to `path` through `path.tmp.<pid>` and rename(2).
// Throws InputError naming the path if the folder is missing or not writable.
void write_file_atomically(const std::string& path, const std::string& content);

}  // namespace pamsim
