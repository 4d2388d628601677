#include "mpi_driver/io/record_spool.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <string_view>

#include <sys/stat.h>

#include "mpi_driver/config/study_hash.hpp"

namespace blockfrag {
namespace {

constexpr std::string_view magic = "BFRECS01";

struct Header {
  char magic[8];
  std::uint64_t config_hash;
  std::int64_t total_samples;
  std::int64_t record_size;
};
static_assert(sizeof(Header) == 32);

std::string system_error(const std::string& what) { return what + ": " + std::strerror(errno); }

void write_all(int fd, const void* data, std::size_t size, off_t offset, const std::string& what) {
  const char* bytes = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t written = ::pwrite(fd, bytes, size, offset);
    if (written < 0) {
      if (errno == EINTR) continue;
      throw FileFailure(system_error("cannot write " + what));
    }
    bytes += written;
    size -= static_cast<std::size_t>(written);
    offset += written;
  }
}

// Reads up to size bytes; what lies past the end of the file reads as zeros.
void read_all(int fd, void* data, std::size_t size, off_t offset, const std::string& what) {
  char* bytes = static_cast<char*>(data);
  while (size > 0) {
    const ssize_t got = ::pread(fd, bytes, size, offset);
    if (got < 0) {
      if (errno == EINTR) continue;
      throw FileFailure(system_error("cannot read " + what));
    }
    if (got == 0) {
      std::memset(bytes, 0, size);
      return;
    }
    bytes += got;
    size -= static_cast<std::size_t>(got);
    offset += got;
  }
}

off_t offset_of(std::int64_t index) {
  return static_cast<off_t>(sizeof(Header)) +
         static_cast<off_t>(index) * static_cast<off_t>(sizeof(SampleRecord));
}

}  // namespace

RecordSpool::RecordSpool(const std::filesystem::path& path, std::uint64_t config_hash,
                         std::int64_t total_samples, Mode mode)
    : path_(path), total_(total_samples) {
  const std::string name = path_.string();
  const int flags = O_RDWR | O_NOFOLLOW | O_CLOEXEC | (mode == Mode::fresh ? O_CREAT : 0);
  fd_ = ::open(name.c_str(), flags, 0644);
  if (fd_ < 0) {
    if (errno == ELOOP) throw RecordSpoolError(name + ": a link, not blockfrag's records file");
    if (errno == ENOENT && mode == Mode::resume) {
      throw RecordSpoolError(name +
                             ": missing: the checkpoint's records are not there; remove the "
                             "checkpoint to start the study over");
    }
    throw FileFailure(system_error("cannot open " + name));
  }
  struct stat status {};
  if (::fstat(fd_, &status) != 0 || !S_ISREG(status.st_mode)) {
    ::close(fd_);
    throw RecordSpoolError(name + ": not a regular file; move it away");
  }
  Header header{};
  if (status.st_size > 0) {
    read_all(fd_, &header, sizeof header, 0, name);
    if (status.st_size < static_cast<off_t>(sizeof header) ||
        std::string_view(header.magic, sizeof header.magic) != magic) {
      ::close(fd_);
      throw RecordSpoolError(name +
                             ": not blockfrag's records file (wrong header); it is left as it is: "
                             "move it away, or choose another --output");
    }
  }
  if (mode == Mode::resume) {
    if (status.st_size == 0 || header.config_hash != config_hash ||
        header.total_samples != total_samples ||
        header.record_size != static_cast<std::int64_t>(sizeof(SampleRecord))) {
      ::close(fd_);
      throw RecordSpoolError(name + ": the records of another study (config hash " +
                             hash_to_hex(header.config_hash) + ", " +
                             std::to_string(header.total_samples) +
                             " samples); remove the checkpoint and this file to start over");
    }
    return;
  }
  // A fresh start: whatever a killed run left is discarded (no checkpoint names it).
  if (::ftruncate(fd_, 0) != 0) {
    ::close(fd_);
    throw FileFailure(system_error("cannot truncate " + name));
  }
  std::memcpy(header.magic, magic.data(), magic.size());
  header.config_hash = config_hash;
  header.total_samples = total_samples;
  header.record_size = sizeof(SampleRecord);
  write_all(fd_, &header, sizeof header, 0, name);
}

RecordSpool::~RecordSpool() {
  if (fd_ >= 0) ::close(fd_);
}

void RecordSpool::write(std::span<const SampleRecord> records) {
  if (records.empty()) return;
  const std::int64_t first = records.front().index;
  const auto count = static_cast<std::int64_t>(records.size());
  if (first < 0 || first + count > total_ || records.back().index != first + count - 1) {
    throw ContractViolation("RecordSpool::write: not consecutive samples of the study");
  }
  write_all(fd_, records.data(), records.size_bytes(), offset_of(first), path_.string());
}

void RecordSpool::read(std::int64_t first, std::span<SampleRecord> out) const {
  if (first < 0 || first + static_cast<std::int64_t>(out.size()) > total_) {
    throw ContractViolation("RecordSpool::read: samples outside the study");
  }
  read_all(fd_, out.data(), out.size_bytes(), offset_of(first), path_.string());
}

void RecordSpool::sync() {
  if (::fsync(fd_) != 0) throw FileFailure(system_error("cannot sync " + path_.string()));
}

std::optional<std::uint64_t> read_record_spool_hash(const std::filesystem::path& path) {
  const std::string name = path.string();
  const int fd = ::open(name.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    if (errno == ENOENT) return std::nullopt;
    if (errno == ELOOP) throw RecordSpoolError(name + ": a link, not blockfrag's records file");
    throw FileFailure(system_error("cannot open " + name));
  }
  struct stat status {};
  Header header{};
  const bool regular = ::fstat(fd, &status) == 0 && S_ISREG(status.st_mode);
  const bool read =
      regular && ::pread(fd, &header, sizeof header, 0) == static_cast<ssize_t>(sizeof header);
  ::close(fd);
  if (!regular) throw RecordSpoolError(name + ": not a regular file; move it away");
  if (status.st_size == 0) return std::nullopt;
  if (!read || std::string_view(header.magic, sizeof header.magic) != magic) {
    throw RecordSpoolError(name +
                           ": not blockfrag's records file (wrong header); it is left as it is: "
                           "move it away, or choose another --output");
  }
  return header.config_hash;
}

std::filesystem::path record_spool_path_for(const std::filesystem::path& output) {
  auto path = output;
  path += ".records";
  return path;
}

}  // namespace blockfrag
