#include "core/output_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "core/errors.h"
#include "core/output_paths.h"
#include "core/text.h"

namespace pond {
namespace fs = std::filesystem;

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

void write_file_atomic(const fs::path& path, std::span<const std::byte> bytes) {
  check_output_path(path);
  std::error_code ec;
  if (fs::exists(path, ec) && !fs::is_regular_file(path, ec)) {
    // A device or pipe (/dev/stdout, /dev/full): there is nothing to clobber and renaming over it
    // would replace the device node, so write straight into it.
    if (int err = write_all(path, bytes))
      throw RuntimeError("cannot write '" + path.string() + "': " + std::strerror(err));
    return;
  }
  // The temporary name carries the pid so that two pond processes never share one.
  fs::path tmp = path;
  tmp += ".tmp." + std::to_string(::getpid());
  if (int err = write_all(tmp, bytes)) {
    std::remove(tmp.c_str());
    throw RuntimeError("cannot write '" + path.string() + "': " + std::strerror(err));
  }
  fs::rename(tmp, path, ec);
  if (ec) {
    std::remove(tmp.c_str());
    throw RuntimeError("cannot write '" + path.string() + "': " + ec.message());
  }
}

std::string read_file(const fs::path& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError("file " + quote(path.string()) + " does not exist");
  if (fs::is_directory(path, ec)) throw InputError(quote(path.string()) + " is a folder, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read " + quote(path.string()));
  std::ostringstream s;
  s << in.rdbuf();
  return std::move(s).str();
}

}  // namespace pond
