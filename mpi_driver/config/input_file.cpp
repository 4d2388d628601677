#include "mpi_driver/config/input_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <sys/stat.h>

namespace blockfrag {
namespace {

// Closes the descriptor on every path out.
class Descriptor {
 public:
  explicit Descriptor(int fd) : fd_(fd) {}
  ~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

}  // namespace

std::string read_input_file(const std::filesystem::path& path, const InputFileRules& rules) {
  const std::string name = path.string();
  int flags = O_RDONLY | O_NONBLOCK | O_CLOEXEC;
  if (!rules.follow_links) flags |= O_NOFOLLOW;
  Descriptor fd(::open(name.c_str(), flags));
  if (fd.get() < 0) {
    const int error = errno;
    if (error == ELOOP && !rules.follow_links) {
      throw InputFileError(name +
                           ": is a symbolic link (refused: this file must be the program's own)");
    }
    if (error == ENOENT) throw InputFileError(name + ": no such file");
    throw InputFileError(name + ": cannot be opened for reading (" + std::strerror(error) + ")");
  }
  struct stat status {};
  if (::fstat(fd.get(), &status) != 0) {
    throw InputFileError(name + ": cannot be examined (" + std::strerror(errno) + ")");
  }
  if (!S_ISREG(status.st_mode)) {
    throw InputFileError(name + ": is " + file_kind(status.st_mode) + ", not a regular file");
  }
  const auto size = static_cast<std::size_t>(status.st_size);
  if (size > rules.max_bytes) {
    throw InputFileError(name + ": is " + std::to_string(size) + " bytes, more than the " +
                         std::to_string(rules.max_bytes) + " this kind of file may have");
  }
  // Reads no more than the cap allows even if the file grows while it is read.
  std::string content(size, '\0');
  std::size_t done = 0;
  while (done < size) {
    const ssize_t got = ::read(fd.get(), content.data() + done, size - done);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw InputFileError(name + ": read error (" + std::strerror(errno) + ")");
    if (got == 0) break;
    done += static_cast<std::size_t>(got);
  }
  content.resize(done);
  return content;
}

std::string printable_excerpt(std::string_view text, std::size_t limit) {
  std::string out;
  for (const char c : text.substr(0, limit)) {
    const auto byte = static_cast<unsigned char>(c);
    out.push_back(byte >= 0x20 && byte < 0x7f ? c : '?');
  }
  if (text.size() > limit) out += "...";
  return out;
}

std::string file_kind(mode_t mode) {
  if (S_ISLNK(mode)) return "a symbolic link";
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

}  // namespace blockfrag
