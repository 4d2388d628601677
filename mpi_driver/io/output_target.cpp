#include "mpi_driver/io/output_target.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <set>

#include <sys/stat.h>

#include "engine/errors.hpp"
#include "mpi_driver/config/input_file.hpp"
#include "mpi_driver/config/output_name.hpp"
#include "mpi_driver/io/atomic_file.hpp"
#include "mpi_driver/io/study_output.hpp"

namespace blockfrag {
namespace {

constexpr std::string_view kHdf5Signature = "\x89HDF\r\n\x1a\n";

// What a file that is not the target's kind is, when blockfrag can tell: another output of its own.
std::string what_else_it_is(const std::filesystem::path& path) {
  if (!file_starts_with(path, kHdf5Signature)) return {};
  const std::string hash = output_config_hash(path);
  return hash.empty() ? std::string(" (an HDF5 file)")
                      : " (a blockfrag study or spectrum output, config hash " + hash + ")";
}

// The target's own rule, refusals worded as "FILE (--option): why; what to do".
struct InputFile {
  std::string description;
  struct stat status;
};

void check_one(const OutputTarget& target, const std::vector<InputFile>& inputs) {
  const std::string name = target.path.string();
  const std::string prefix = name.empty()
                                 ? target.option + ": "
                                 : printable_excerpt(name, 200) + " (" + target.option + "): ";
  const std::string choose = "; choose another " + target.option;
  if (const auto problem = output_name_problem(name)) throw InvalidInput(prefix + *problem);
  if (const auto problem = folder_write_problem(target.path)) {
    throw InvalidInput(prefix + *problem);
  }
  struct stat status {};
  if (::lstat(name.c_str(), &status) != 0) {
    if (errno == ENOENT) return;
    throw InvalidInput(prefix + "cannot be examined (" + std::strerror(errno) + ")");
  }
  if (!S_ISREG(status.st_mode)) {
    throw InvalidInput(prefix + "is " + file_kind(status.st_mode) +
                       "; blockfrag replaces only regular files it wrote itself" + choose);
  }
  for (const auto& input : inputs) {
    if (input.status.st_dev == status.st_dev && input.status.st_ino == status.st_ino) {
      throw InvalidInput(prefix + "is this command's input, " + input.description + choose);
    }
  }
  if (!target.is_own(target.path)) {
    throw InvalidInput(prefix + "refusing to replace an existing file that is not " + target.kind +
                       what_else_it_is(target.path) + "; remove it or choose another " +
                       target.option);
  }
}

}  // namespace

void check_output_targets(const std::vector<OutputTarget>& targets,
                          const std::vector<CommandInput>& inputs) {
  std::vector<InputFile> input_files;
  for (const auto& input : inputs) {
    struct stat status {};
    if (::stat(input.path.c_str(), &status) == 0) {
      input_files.push_back(
          {input.what + " " + printable_excerpt(input.path.string(), 200), status});
    }
  }
  std::set<std::filesystem::path> seen;
  for (const auto& target : targets) {
    check_one(target, input_files);
    std::error_code error;
    auto resolved =
        std::filesystem::weakly_canonical(std::filesystem::absolute(target.path), error);
    if (error) resolved = target.path.lexically_normal();
    if (!seen.insert(resolved).second) {
      throw InvalidInput(printable_excerpt(target.path.string(), 200) + " (" + target.option +
                         "): names the same file as another of this command's outputs; give "
                         "each its own name");
    }
  }
}

bool file_starts_with(const std::filesystem::path& path, std::string_view leading,
                      std::string_view marker, std::size_t limit) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return false;
  struct stat status {};
  std::string head;
  if (::fstat(fd, &status) == 0 && S_ISREG(status.st_mode)) {
    head.resize(std::max(limit, leading.size()));
    std::size_t done = 0;
    while (done < head.size()) {
      const ssize_t got = ::read(fd, head.data() + done, head.size() - done);
      if (got < 0 && errno == EINTR) continue;
      if (got <= 0) break;
      done += static_cast<std::size_t>(got);
    }
    head.resize(done);
  }
  ::close(fd);
  return head.starts_with(leading) && (marker.empty() || head.find(marker) != std::string::npos);
}

}  // namespace blockfrag
