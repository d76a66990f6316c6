#include "core/output_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/errors.h"
#include "core/interrupt.h"
#include "core/output_paths.h"
#include "core/text.h"

namespace pond {
namespace fs = std::filesystem;

// What a file that is not a regular one (a FIFO, a device) may give before it is cut off.
constexpr std::size_t kMaxStreamBytes = std::size_t{1} << 30;

void check_output_path(const fs::path& path) {
  if (path.empty()) throw InputError("output path is empty");
  fs::path folder = path.parent_path();
  if (folder.empty()) folder = ".";
  std::error_code ec;
  if (!fs::is_directory(folder, ec))
    throw InputError("output folder " + quote(folder.string()) + " does not exist");
  check_name_length(path, folder);
  if (fs::is_directory(path, ec))
    throw InputError("output path " + quote(path.string()) + " is a folder");
  if (::access(folder.c_str(), W_OK) != 0)
    throw InputError("output folder " + quote(folder.string()) + " is not writable");
  // access() says yes to root everywhere but on read-only mounts, and procfs or sysfs refuse new
  // files whatever it says: so try to create one (unless the target is an existing device or pipe,
  // written in place), so that an unwritable folder fails now and as bad input, not after the run.
  if (fs::exists(path, ec) && !fs::is_regular_file(path, ec)) return;
  const fs::path probe = folder / (".pond-probe." + std::to_string(::getpid()));
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (const int err = fd < 0 ? errno : 0; err && err != EEXIST)
    throw InputError("output folder " + quote(folder.string()) + " is not writable: " + std::strerror(err));
  if (fd >= 0) {
    ::close(fd);
    ::unlink(probe.c_str());
  }
}

namespace {
// Writes and flushes; returns 0 or the errno of the first failure.
int write_all(const fs::path& target, std::span<const std::byte> bytes) {
  std::FILE* f = std::fopen(target.c_str(), "wb");
  if (!f) return errno;
  int err = 0;
  if (std::fwrite(bytes.data(), 1, bytes.size(), f) != bytes.size()) err = errno ? errno : EIO;
  if (!err && std::fflush(f) != 0) err = errno;
  if (std::fclose(f) != 0 && !err) err = errno;
  return err;
}
}  // namespace

void write_file_atomic(const fs::path& path, std::span<const std::byte> bytes, const fs::path& shown_as) {
  check_output_path(path);
  const std::string name = quote((shown_as.empty() ? path : shown_as).string());
  std::error_code ec;
  if (fs::exists(path, ec) && !fs::is_regular_file(path, ec)) {
    // A device or pipe (/dev/stdout, /dev/full): there is nothing to clobber and renaming over it
    // would replace the device node, so write straight into it.
    if (int err = write_all(path, bytes))
      throw RuntimeError("cannot write " + name + ": " + std::strerror(err));
    return;
  }
  // The temporary name carries the pid so that two pond processes never share one.
  fs::path tmp = path;
  tmp += ".tmp." + std::to_string(::getpid());
  set_temporary_file(tmp.c_str());  // a signal that ends pond now removes it
  if (int err = write_all(tmp, bytes)) {
    std::remove(tmp.c_str());
    set_temporary_file(nullptr);
    throw RuntimeError("cannot write " + name + ": " + std::strerror(err));
  }
  fs::rename(tmp, path, ec);
  if (ec) std::remove(tmp.c_str());
  set_temporary_file(nullptr);
  if (ec) throw RuntimeError("cannot write " + name + ": " + ec.message());
  count_file_written();
}

std::string read_file(const fs::path& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError("file " + quote(path.string()) + " does not exist");
  if (fs::is_directory(path, ec)) throw InputError(quote(path.string()) + " is a folder, not a file");
  // open() and read() by hand: a FIFO without a writer blocks in open(), and a signal while a
  // command polls (core/interrupt.h) interrupts either; a device that never ends is cut off.
  int fd = -1;
  while ((fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC)) < 0 && errno == EINTR)
    throw_if_interrupted("while opening " + quote(path.string()));
  if (fd < 0) throw InputError("cannot read " + quote(path.string()) + ": " + std::strerror(errno));
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  const bool regular = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
  std::string out;
  if (regular) out.reserve(static_cast<std::size_t>(st.st_size));
  const std::string reading = "while reading " + quote(path.string());
  char chunk[1 << 16];
  for (;;) {
    // A signal ends the read whether it interrupted read() or came between two chunks of a file
    // that never ends (/dev/zero).
    throw_if_interrupted(reading);
    const ssize_t n = ::read(fd, chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw InputError("cannot read " + quote(path.string()) + ": " + std::strerror(errno));
    if (n == 0) break;
    out.append(chunk, static_cast<std::size_t>(n));
    if (!regular && out.size() > kMaxStreamBytes)
      throw InputError(quote(path.string()) + " is not a regular file and gave more than " +
                       std::to_string(kMaxStreamBytes >> 20) + " MiB without ending");
  }
  return out;
}

}  // namespace pond
