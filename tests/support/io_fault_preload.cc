// An LD_PRELOAD library that makes one kind of file operation fail, so that tests can
// run the real apps against a full disk or an output folder that turned unwritable
// without any test hook in the apps. Environment:
//   DDB_IO_FAULT_PATH  a substring of the file's path; only such files fail
//   DDB_IO_FAULT_OP    write  fwrite/fflush to the file fail with ENOSPC (disk full)
//                      fsync  fsync of the file fails with ENOSPC (full at flush time)
//                      create mkstemp or fopen for writing of a matching name fails with
//                             EACCES (the folder became unwritable)
//                      rename rename onto a matching target fails with EACCES
//   DDB_IO_FAULT_AFTER the number of matching calls that succeed before the faults begin
//                      (default 0): a disk that fills in the middle of a run
// Every call that is not matched goes on to the real function. The apps write through
// stdio and call fsync, mkstemp and rename themselves, so these are the calls they make;
// glibc's internal write() from fflush cannot be interposed, hence fwrite and fflush.
#include <dlfcn.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace {

bool faultOn(const char* op, const std::string& path) {
  const char* wanted_op = std::getenv("DDB_IO_FAULT_OP");
  const char* pattern = std::getenv("DDB_IO_FAULT_PATH");
  if (wanted_op == nullptr || pattern == nullptr || std::strcmp(wanted_op, op) != 0 ||
      path.find(pattern) == std::string::npos) {
    return false;
  }
  static const char* after = std::getenv("DDB_IO_FAULT_AFTER");
  static long matched = 0;
  return ++matched > (after != nullptr ? std::atol(after) : 0);
}

/// The path an open descriptor refers to, from /proc/self/fd.
std::string pathOf(int fd) {
  char link[64], target[4096];
  std::snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
  const ssize_t n = ::readlink(link, target, sizeof target - 1);
  return n > 0 ? std::string(target, static_cast<std::size_t>(n)) : std::string();
}

bool failsWriting(std::FILE* file, const char* op) {
  return file != nullptr && faultOn(op, pathOf(::fileno(file)));
}

template <class F>
F real(const char* name) {
  return reinterpret_cast<F>(::dlsym(RTLD_NEXT, name));
}

/// fopen or fopen64 (`real_name`), failing with EACCES for a matching name opened to write.
std::FILE* openFor(const char* name, const char* mode, const char* real_name) {
  if (mode[0] != 'r' && faultOn("create", name)) {
    errno = EACCES;
    return nullptr;
  }
  return real<std::FILE* (*)(const char*, const char*)>(real_name)(name, mode);
}

}  // namespace

extern "C" {

std::size_t fwrite(const void* data, std::size_t size, std::size_t count, std::FILE* file) {
  if (failsWriting(file, "write")) {
    errno = ENOSPC;
    return 0;
  }
  static const auto next =
      real<std::size_t (*)(const void*, std::size_t, std::size_t, FILE*)>("fwrite");
  return next(data, size, count, file);
}

int fflush(std::FILE* file) {
  if (failsWriting(file, "write")) {
    errno = ENOSPC;
    return EOF;
  }
  static const auto next = real<int (*)(std::FILE*)>("fflush");
  return next(file);
}

int fsync(int fd) {
  if (faultOn("fsync", pathOf(fd))) {
    errno = ENOSPC;
    return -1;
  }
  static const auto next = real<int (*)(int)>("fsync");
  return next(fd);
}

int mkstemp(char* name) {
  if (faultOn("create", name)) {
    errno = EACCES;
    return -1;
  }
  static const auto next = real<int (*)(char*)>("mkstemp");
  return next(name);
}

// Journal files (history.csv's `.partial`) are created by fopen (fopen64) for writing.
std::FILE* fopen(const char* name, const char* mode) { return openFor(name, mode, "fopen"); }

std::FILE* fopen64(const char* name, const char* mode) { return openFor(name, mode, "fopen64"); }

int rename(const char* from, const char* to) {
  if (faultOn("rename", to)) {
    errno = EACCES;
    return -1;
  }
  static const auto next = real<int (*)(const char*, const char*)>("rename");
  return next(from, to);
}

}  // extern "C"
