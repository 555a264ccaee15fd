// Reading a table image file inside rtapi_app (see the header).
#include "table_file.hpp"

#include <fcntl.h>
#include <pwd.h>
#include <sys/fsuid.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "volcomp/table/table_format.hpp"

namespace volcomp::linuxcnc {
namespace {

std::string UserName(uid_t uid) {
  const passwd* p = getpwuid(uid);
  return p != nullptr ? std::string(" (") + p->pw_name + ")" : std::string();
}

std::string Quoted(const std::string& path) { return "\"" + path + "\""; }

// Why the process cannot open `path`: errno's text and, for a permission error, who reads and who
// owns the file (rtapi_app reads files as RTAPI_UID or the invoking user, not as the file's owner).
std::string OpenFailure(const std::string& path, int err) {
  std::string m = "cannot read table " + Quoted(path) + ": " + std::strerror(err);
  if (!path.empty() && path[0] != '/') {
    char cwd[4096];
    if (getcwd(cwd, sizeof cwd) != nullptr)
      m += " (the path is relative to " + std::string(cwd) + ")";
  }
  if (err == EACCES || err == EPERM) {
    // The uid the kernel checks file access with (rtapi_app may keep euid 0 and read as RTAPI_UID).
    const uid_t reader = static_cast<uid_t>(setfsuid(static_cast<uid_t>(-1)));
    char buf[96];
    std::snprintf(buf, sizeof buf, " (rtapi_app reads as uid %u", static_cast<unsigned>(reader));
    m += buf + UserName(reader);
    struct stat st;
    if (stat(path.c_str(), &st) == 0) {
      std::snprintf(buf, sizeof buf, "; the file: uid %u", static_cast<unsigned>(st.st_uid));
      m += buf + UserName(st.st_uid);
      std::snprintf(buf, sizeof buf, ", mode %04o", static_cast<unsigned>(st.st_mode & 07777));
      m += buf;
    }
    m += ")";
  }
  return m;
}

}  // namespace

Expected<std::vector<uint8_t>> ReadTableFile(const std::string& path) {
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    const int err = errno;
    return Fail(err == ENOENT ? Error::kNotFound : Error::kIoError, OpenFailure(path, err));
  }
  std::vector<uint8_t> bytes;
  uint8_t buf[65536];
  for (;;) {
    const ssize_t n = read(fd, buf, sizeof buf);
    if (n < 0) {
      if (errno == EINTR) continue;
      const std::string m = "cannot read table " + Quoted(path) + ": " + std::strerror(errno);
      close(fd);
      return Fail(Error::kIoError, m);
    }
    if (n == 0) break;
    bytes.insert(bytes.end(), buf, buf + n);
    if (bytes.size() > table::kMaxImageSize) {
      close(fd);
      return Fail(Error::kImageTooLarge, ImageRefusal(path, Error::kImageTooLarge));
    }
  }
  close(fd);
  return bytes;
}

std::string ImageRefusal(const std::string& path, Status status) {
  return "table " + Quoted(path) + " refused: invalid table image: " + ErrorText(status.error()) +
         " (" + status.name() + ")";
}

}  // namespace volcomp::linuxcnc
