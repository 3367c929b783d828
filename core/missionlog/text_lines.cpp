#include "missionlog/text_lines.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>

#include "common/input_error.h"

namespace auv {

BlockFile::BlockFile(const std::filesystem::path& path) : name_(path.string()) {
  fd_ = ::open(name_.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd_ < 0)
    throw InputError("log", std::string("cannot open file: ") + std::strerror(errno),
                     "check the path and the file permissions", {name_, 0, 0});
  struct stat st {};
  if (::fstat(fd_, &st) != 0 || S_ISDIR(st.st_mode)) {
    ::close(fd_);
    fd_ = -1;
    throw InputError("log", "not a regular file", "give the path of a log file", {name_, 0, 0});
  }
  ::posix_fadvise(fd_, 0, 0, POSIX_FADV_SEQUENTIAL);
  size_ = static_cast<std::uint64_t>(st.st_size > 0 ? st.st_size : 0);
}

BlockFile::~BlockFile() {
  if (fd_ >= 0) ::close(fd_);
}

std::size_t BlockFile::read(char* dst, std::size_t n) {
  for (;;) {
    const ssize_t r = ::read(fd_, dst, n);
    if (r >= 0) return static_cast<std::size_t>(r);
    if (errno == EINTR) continue;
    throw InputError("log", std::string("read error: ") + std::strerror(errno),
                     "check the disk or copy the file again", {name_, 0, 0});
  }
}

}  // namespace auv
