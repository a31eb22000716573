// Little-endian byte helpers, FNV-1a and write-then-rename (dslam/core/binary_io.h and
// dslam/core/atomic_file.h).
#include "dslam/core/binary_io.h"

#include "dslam/core/atomic_file.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace dslam {

void PutU32(std::uint32_t v, std::string* out) {
  for (int i = 0; i < 4; ++i) out->push_back(static_cast<char>((v >> (8 * i)) & 0xFFu));
}

void PutU64(std::uint64_t v, std::string* out) {
  for (int i = 0; i < 8; ++i) out->push_back(static_cast<char>((v >> (8 * i)) & 0xFFu));
}

void PutF64(double v, std::string* out) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &v, sizeof(double));
  PutU64(bits, out);
}

std::uint64_t GetLittleEndian(const std::string& bytes, std::size_t offset, int size) {
  std::uint64_t v = 0;
  for (int i = 0; i < size; ++i) {
    v |= static_cast<std::uint64_t>(static_cast<std::uint8_t>(bytes[offset + i])) << (8 * i);
  }
  return v;
}

double GetF64(const std::string& bytes, std::size_t offset) {
  const std::uint64_t bits = GetLittleEndian(bytes, offset, 8);
  double v = 0.0;
  std::memcpy(&v, &bits, sizeof(double));
  return v;
}

std::uint64_t Fnv1a64Update(std::uint64_t hash, const char* data, std::size_t size) {
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= static_cast<std::uint8_t>(data[i]);
    hash *= 1099511628211ull;
  }
  return hash;
}

std::uint64_t Fnv1a64(const char* data, std::size_t size) {
  return Fnv1a64Update(kFnv1a64Basis, data, size);
}

std::string FormatIdentity(std::uint64_t identity) {
  char text[17];
  std::snprintf(text, sizeof(text), "%016llx", static_cast<unsigned long long>(identity));
  return text;
}

namespace {

std::atomic<unsigned long long> temporary_count{0};

// `path` + ".tmp-<pid>-<n>": unique among the files this process names so, and among processes.
std::string TemporaryPath(const std::string& path) {
  return path + ".tmp-" + std::to_string(::getpid()) + "-" +
         std::to_string(temporary_count.fetch_add(1, std::memory_order_relaxed));
}

std::string ErrnoText(int error) {
  return std::error_code(error, std::generic_category()).message();
}

// fsync of the file (opened for writing) or folder at `path`: 0, or the errno of the failure.
// On Linux fsync flushes the file's data however it was written (the page cache is per file).
int SyncPath(const std::string& path, bool folder) {
  const int fd = ::open(path.c_str(), (folder ? O_RDONLY | O_DIRECTORY : O_WRONLY) | O_CLOEXEC);
  if (fd < 0) return errno;
  const int error = ::fsync(fd) == 0 ? 0 : errno;
  ::close(fd);
  return error;
}

std::string FolderOf(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return parent.empty() ? "." : parent.string();
}

void RemoveQuietly(const std::string& path) {
  std::error_code ignored;
  std::filesystem::remove(path, ignored);
}

// Writes `temporary` through `write`, closes and fsyncs it; throws "<who>: cannot write ...".
void WriteTemporary(const std::string& temporary, const std::function<void(std::ostream&)>& write,
                    const std::string& who) {
  std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error(who + ": cannot write " + temporary);
  write(out);
  out.close();
  if (!out) throw std::runtime_error(who + ": cannot write " + temporary);
  const int error = SyncPath(temporary, false);
  if (error != 0) {
    throw std::runtime_error(who + ": cannot write " + temporary +
                             ": cannot sync: " + ErrnoText(error));
  }
}

void Rename(const std::string& from, const std::string& to, const std::string& who) {
  std::error_code error;
  std::filesystem::rename(from, to, error);
  if (error) {
    throw std::runtime_error(who + ": cannot rename " + from + " to " + to + ": " +
                             error.message());
  }
}

// The file at `path`, if there is one, as `path` + ".prev": a hard link (a synced copy where
// links fail) made under a temporary name and renamed over an older ".prev".
void KeepPrevious(const std::string& path, const std::string& who) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) return;
  const std::string previous = path + ".prev";
  const std::string staged = TemporaryPath(previous);
  if (::link(path.c_str(), staged.c_str()) != 0) {
    std::filesystem::copy_file(path, staged, error);
    if (!error && SyncPath(staged, false) != 0) error = std::make_error_code(std::errc::io_error);
    if (error) {
      RemoveQuietly(staged);
      throw std::runtime_error(who + ": cannot keep " + path + " as " + previous + ": " +
                               error.message());
    }
  }
  try {
    Rename(staged, previous, who);
  } catch (...) {
    RemoveQuietly(staged);
    throw;
  }
}

// Whether `name` is `prefix` + "<pid>-<n>" (TemporaryPath's form) of a process that no longer
// exists (kill(pid, 0) fails with ESRCH; a process of another user answers EPERM and counts as
// alive).
bool IsTemporaryOfEndedProcess(const std::string& name, const std::string& prefix) {
  if (name.rfind(prefix, 0) != 0) return false;
  const std::string rest = name.substr(prefix.size());
  const size_t dash = rest.find('-');
  if (dash == 0 || dash == std::string::npos || dash + 1 == rest.size()) return false;
  if (rest.find_first_not_of("0123456789") != dash) return false;
  if (rest.find_first_not_of("0123456789", dash + 1) != std::string::npos) return false;
  if (dash > 9) return false;  // beyond any pid
  const pid_t pid = static_cast<pid_t>(std::stol(rest.substr(0, dash)));
  return pid > 0 && ::kill(pid, 0) != 0 && errno == ESRCH;
}

// Removes the temporary files of `path` and of `path` + ".prev" that processes killed while
// saving left behind (those of running processes stay: they may be saving now).
void RemoveTemporariesOfEndedProcesses(const std::string& path) {
  const std::filesystem::path file(path);
  const std::string name = file.filename().string();
  const std::string prefixes[2] = {name + ".tmp-", name + ".prev.tmp-"};
  std::error_code error;
  for (std::filesystem::directory_iterator it(FolderOf(path), error), end; !error && it != end;
       it.increment(error)) {
    const std::string entry = it->path().filename().string();
    for (const std::string& prefix : prefixes) {
      if (IsTemporaryOfEndedProcess(entry, prefix)) RemoveQuietly(it->path().string());
    }
  }
}

}  // namespace

void WriteFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                         const std::string& who, PreviousFile previous) {
  const std::string temporary = TemporaryPath(path);
  try {
    WriteTemporary(temporary, write, who);
    if (previous == PreviousFile::kKeep) KeepPrevious(path, who);
    Rename(temporary, path, who);
  } catch (...) {
    RemoveQuietly(temporary);
    throw;
  }
  RemoveTemporariesOfEndedProcesses(path);
  const std::string folder = FolderOf(path);
  const int error = SyncPath(folder, true);
  if (error != 0 && error != EINVAL) {  // EINVAL: a file system that cannot sync folders
    throw std::runtime_error(who + ": wrote " + path + " but cannot sync its folder " + folder +
                             ": " + ErrnoText(error));
  }
}

void WriteFileAtomically(const std::string& path, const std::string& bytes,
                         const std::string& who) {
  WriteFileAtomically(
      path,
      [&](std::ostream& out) {
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
      },
      who);
}

std::string ReadWholeFile(const std::string& path, const std::string& who) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(who + ": " + path + ": cannot open the file");
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw std::runtime_error(who + ": " + path + ": read error");
  return bytes;
}

}  // namespace dslam
