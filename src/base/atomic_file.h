// atomic_file.h: write an output file all at once (temp file in the same folder, then
// rename), so a reader never sees half a file and a failed run leaves none behind.
#pragma once

#include <string>

namespace pamsim {

// True for "-" (standard output) and for an existing path that is neither a regular file nor
// a folder (a terminal, /dev/stdout, a FIFO): such an output is a stream, written through
// as it is; replacing it by a rename would turn /dev/stdout into a regular file.
bool is_stream_output(const std::string& path);

// Writes all of `content` to the stream output `path` ("-": standard output, after what
// std::cout holds). Throws InputError "<path>: write failed (why)".
void write_stream_output(const std::string& path, const std::string& content);

// Writes `content` to `path` (a stream output: written through, see is_stream_output)
// through a temp file `path.tmp.XXXXXX` made by mkostemp
// (created exclusively: a file or symlink planted at a predictable name is never written
// through), written whole and fsync'd, then rename(2). The file gets the permissions a
// plain create would (0666 less the umask). Throws InputError naming the path if the
// folder is missing or not writable, or a write fails (a full disk); nothing is left.
void write_file_atomically(const std::string& path, const std::string& content);

// What to make beside an output before it is renamed into place.
enum class TempKind { kFile, kFolder };

// Creates `<path>.tmp.XXXXXX` beside `path`, exclusively (mkostemp or mkdtemp: never an
// existing name, never through a planted symlink), with the permissions a plain create
// would give (0666 or 0777 less the umask); returns its name. For a file, `*fd` receives
// the open descriptor when `fd` is given (it is closed otherwise). Throws InputError
// "<path>: cannot write (why)".
std::string make_temp_beside(const std::string& path, TempKind kind, int* fd = nullptr);

}  // namespace pamsim
