// atomic_file.cc: temp file + rename, see atomic_file.h.
#include "base/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <vector>

#include "base/input_error.h"

namespace pamsim {

namespace {

// The process's umask, read without changing it for long (umask(2) has no getter).
mode_t current_umask() {
  const mode_t mask = ::umask(022);
  ::umask(mask);
  return mask;
}

}  // namespace

std::string make_temp_beside(const std::string& path, TempKind kind, int* fd_out) {
  // an unpredictable name, created exclusively (O_CREAT | O_EXCL, so neither an existing
  // file nor a planted symlink is ever opened), in the destination folder so that the
  // rename into place stays on one file system
  std::vector<char> tmp(path.begin(), path.end());
  const std::string suffix = ".tmp.XXXXXX";
  tmp.insert(tmp.end(), suffix.begin(), suffix.end());
  tmp.push_back('\0');
  const auto fail = [&](const char* what) {
    throw InputError(path + ": " + what + " (" + std::strerror(errno) + ")");
  };
  if (kind == TempKind::kFolder) {
    if (!::mkdtemp(tmp.data())) fail("cannot write");
    // the permissions a plain mkdir would give (mkdtemp makes 0700)
    if (::chmod(tmp.data(), 0777 & ~current_umask()) != 0) {
      const int saved = errno;
      ::rmdir(tmp.data());
      errno = saved;
      fail("cannot set permissions");
    }
    return tmp.data();
  }
  const int fd = ::mkostemp(tmp.data(), O_CLOEXEC);
  if (fd < 0) fail("cannot write");
  // the permissions a plain create would give (mkstemp makes 0600)
  if (::fchmod(fd, 0666 & ~current_umask()) != 0) {
    const int saved = errno;
    ::close(fd);
    ::unlink(tmp.data());
    errno = saved;
    fail("cannot set permissions");
  }
  if (fd_out) {
    *fd_out = fd;
  } else {
    ::close(fd);
  }
  return tmp.data();
}

bool is_stream_output(const std::string& path) {
  if (path == "-") return true;
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return false;  // (a new file)
  return !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode);
}

void write_stream_output(const std::string& path, const std::string& content) {
  int fd = 1;
  if (path == "-") {
    std::cout.flush();
    std::fflush(stdout);
  } else {
    fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) throw InputError(path + ": cannot write (" + std::strerror(errno) + ")");
  }
  const char* data = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, data, left);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const std::string why = std::strerror(errno);
      if (fd != 1) ::close(fd);
      throw InputError(path + ": write failed (" + why + ")");
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  if (fd != 1) ::close(fd);
}

void write_file_atomically(const std::string& path, const std::string& content) {
  if (is_stream_output(path)) return write_stream_output(path, content);
  int fd = -1;
  const std::string tmp = make_temp_beside(path, TempKind::kFile, &fd);
  const auto fail = [&](const char* what) {
    const std::string why = std::strerror(errno);
    ::close(fd);
    ::unlink(tmp.c_str());
    throw InputError(path + ": " + what + " (" + why + ")");
  };

  // write everything (a full disk shows here), then publish it in one step
  const char* data = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, data, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail("write failed");
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) fail("write failed");
  if (::close(fd) != 0) {
    const std::string why = std::strerror(errno);
    ::unlink(tmp.c_str());
    throw InputError(path + ": write failed (" + why + ")");
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    ::unlink(tmp.c_str());
    throw InputError(path + ": cannot rename temp file into place (" + why + ")");
  }
}

}  // namespace pamsim
