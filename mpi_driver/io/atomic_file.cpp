#include "mpi_driver/io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>

namespace blockfrag {
namespace {

std::string system_error_text(const std::string& what, const std::filesystem::path& path) {
  return what + " " + path.string() + ": " + std::strerror(errno);
}

void fsync_path(const std::filesystem::path& path, int flags) {
  const int fd = ::open(path.c_str(), flags);
  if (fd < 0) throw FileError(system_error_text("cannot open", path));
  const int status = ::fsync(fd);
  ::close(fd);
  if (status != 0) throw FileError(system_error_text("cannot fsync", path));
}

std::filesystem::path folder_of(const std::filesystem::path& path) {
  const auto parent = path.parent_path();
  return parent.empty() ? std::filesystem::path(".") : parent;
}

}  // namespace

std::filesystem::path temporary_path_for(const std::filesystem::path& path) {
  auto temporary = path;
  temporary += ".tmp";
  return temporary;
}

void replace_file_atomically(const std::filesystem::path& path,
                             const std::function<void(const std::filesystem::path&)>& write_temporary,
                             const AtomicWriteHooks& hooks) {
  const auto temporary = temporary_path_for(path);
  write_temporary(temporary);
  fsync_path(temporary, O_RDONLY);
  if (hooks.pause_before_rename_s > 0.0) {
    std::this_thread::sleep_for(std::chrono::duration<double>(hooks.pause_before_rename_s));
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    throw FileError(system_error_text("cannot rename " + temporary.string() + " to", path));
  }
  fsync_path(folder_of(path), O_RDONLY | O_DIRECTORY);
}

void write_file_atomically(const std::filesystem::path& path, std::string_view bytes,
                           const AtomicWriteHooks& hooks) {
  replace_file_atomically(
      path,
      [&](const std::filesystem::path& temporary) {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        out.close();
        if (!out) throw FileError("cannot write " + temporary.string());
      },
      hooks);
}

std::string read_whole_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError("cannot open " + path.string());
  std::ostringstream content;
  content << in.rdbuf();
  if (!in && !in.eof()) throw FileError("cannot read " + path.string());
  return content.str();
}

}  // namespace blockfrag
