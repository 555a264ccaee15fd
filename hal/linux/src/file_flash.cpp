// File-backed NOR flash.
#include "volcomp/hal/linux/file_flash.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>

namespace volcomp::hal::linux_board {
namespace {

Unexpected<Failure> Why(const std::string& path, const char* what) {
  return Fail(Error::kIoError, "flash file " + path + ": " + what + ": " + std::strerror(errno));
}

bool WriteAll(int fd, const uint8_t* p, size_t n, off_t at) {
  while (n > 0) {
    const ssize_t w = ::pwrite(fd, p, n, at);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    p += w;
    n -= static_cast<size_t>(w);
    at += w;
  }
  return true;
}

std::string DirOf(const std::string& path) {
  const size_t slash = path.rfind('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

// Creates `path` at `size` bytes of 0xFF: temporary file, fsync, rename, fsync of the directory.
Expected<void> CreateErased(const std::string& path, uint32_t size) {
  const std::string tmp = path + ".tmp";
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return Why(tmp, "cannot create");
  const std::vector<uint8_t> erased(size, 0xFF);
  if (!WriteAll(fd, erased.data(), erased.size(), 0) || ::fsync(fd) != 0) {
    const Unexpected<Failure> why = Why(tmp, "cannot write");
    ::close(fd);
    ::unlink(tmp.c_str());
    return why;
  }
  ::close(fd);
  if (::rename(tmp.c_str(), path.c_str()) != 0) return Why(path, "cannot rename into place");
  const int dir = ::open(DirOf(path).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
  return Expected<void>::Ok();
}

}  // namespace

Expected<void> FileFlash::Open(const std::string& path, const Options& options) {
  Close();
  if (options.size == 0 || options.sector_size == 0 || options.program_unit == 0 ||
      options.size % options.sector_size != 0 || options.sector_size % options.program_unit != 0) {
    return Fail(Error::kInvalidArgument, "flash file " + path +
                                             ": size must be a multiple of the sector size, and "
                                             "the sector size a multiple of the program unit");
  }
  options_ = options;
  path_ = path;
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    if (errno != ENOENT) return Why(path, "cannot stat");
    const Expected<void> created = CreateErased(path, options.size);
    if (!created.ok()) return Fail(created.error());
  } else if (!S_ISREG(st.st_mode)) {
    return Fail(Error::kConfigInvalid, "flash file " + path + ": not a regular file");
  } else if (static_cast<uint64_t>(st.st_size) != options.size) {
    return Fail(Error::kConfigInvalid, "flash file " + path + ": size is " +
                                           std::to_string(st.st_size) + " bytes, expected " +
                                           std::to_string(options.size) +
                                           " (another layout; move it away to start empty)");
  }
  fd_ = ::open(path.c_str(), O_RDWR | O_CLOEXEC);
  if (fd_ < 0) return Why(path, "cannot open");
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const Unexpected<Failure> why =
        errno == EWOULDBLOCK
            ? Fail(Error::kBusy, "flash file " + path + ": in use by another process")
            : Why(path, "cannot lock");
    Close();
    return why;
  }
  storage_.assign((options.size + 7) / 8, ~uint64_t{0});
  size_t done = 0;
  while (done < options.size) {
    const ssize_t r = ::pread(fd_, bytes() + done, options.size - done, static_cast<off_t>(done));
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) {
      const Unexpected<Failure> why = Why(path, "cannot read");
      Close();
      return why;
    }
    done += static_cast<size_t>(r);
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    counters_ = Counters();
    error_.reset();
    queue_.clear();
    stop_ = busy_ = false;
  }
  if (options.background) writer_ = std::thread([this] { WriterLoop(); });
  return Expected<void>::Ok();
}

void FileFlash::Close() {
  if (writer_.joinable()) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    wake_.notify_all();
    writer_.join();  // the writer drains the queue before it stops
  }
  if (fd_ >= 0) ::close(fd_);  // also releases the lock
  fd_ = -1;
}

Expected<void> FileFlash::Flush() {
  std::unique_lock<std::mutex> lock(mutex_);
  idle_.wait(lock, [this] { return (queue_.empty() && !busy_) || !writer_.joinable(); });
  if (error_) return Fail(*error_);
  return Expected<void>::Ok();
}

FileFlash::Counters FileFlash::counters() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return counters_;
}

std::optional<Failure> FileFlash::write_error() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return error_;
}

Expected<void> FileFlash::WriteOp(const uint8_t* data, uint32_t size, uint32_t offset) {
  if (!WriteAll(fd_, data, size, static_cast<off_t>(offset)) ||
      (options_.sync && ::fdatasync(fd_) != 0)) {
    return Why(path_, "write failed");
  }
  return Expected<void>::Ok();
}

void FileFlash::WriterLoop() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    wake_.wait(lock, [this] { return stop_ || !queue_.empty(); });
    if (queue_.empty()) break;  // stop_ with nothing left
    Op op = std::move(queue_.front());
    queue_.pop_front();
    busy_ = true;
    const bool failed = error_.has_value();
    lock.unlock();
    const Expected<void> written =
        failed ? Expected<void>::Ok()
               : WriteOp(op.bytes.data(), static_cast<uint32_t>(op.bytes.size()), op.offset);
    lock.lock();
    busy_ = false;
    if (!written.ok() && !error_) error_ = written.error();
    if (written.ok() && !failed) ++counters_.written;
    if (queue_.empty()) idle_.notify_all();
  }
  idle_.notify_all();
}

Status FileFlash::Submit(uint32_t offset, uint32_t size) {
  if (!options_.background) {
    const Expected<void> written = WriteOp(bytes() + offset, size, offset);
    std::lock_guard<std::mutex> lock(mutex_);
    if (!written.ok()) {
      if (!error_) error_ = written.error();
      return Error::kIoError;
    }
    ++counters_.written;
    return Status::Ok();
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    queue_.push_back(Op{offset, std::vector<uint8_t>(bytes() + offset, bytes() + offset + size)});
    if (queue_.size() > counters_.max_queued) counters_.max_queued = queue_.size();
  }
  wake_.notify_one();
  return Status::Ok();
}

Status FileFlash::DoErase(uint32_t offset) {
  if (fd_ < 0) return Error::kNotReady;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (error_) return Error::kIoError;
    ++counters_.erases;
  }
  std::memset(bytes() + offset, 0xFF, options_.sector_size);
  return Submit(offset, options_.sector_size);
}

Status FileFlash::DoProgram(uint32_t offset, const uint8_t* data, uint32_t size) {
  if (fd_ < 0) return Error::kNotReady;
  uint8_t* dst = bytes() + offset;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    bool refused = error_.has_value();
    for (uint32_t i = 0; i < size && !refused; ++i) {
      refused = (dst[i] & data[i]) != data[i];  // NOR: programming cannot set a bit
    }
    if (refused) {
      ++counters_.refused;
      return Error::kIoError;
    }
    ++counters_.programs;
  }
  std::memcpy(dst, data, size);
  return Submit(offset, size);
}

}  // namespace volcomp::hal::linux_board
