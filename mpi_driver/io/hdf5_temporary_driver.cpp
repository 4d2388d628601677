#include "mpi_driver/io/hdf5_temporary_driver.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <iterator>
#include <new>

#include <sys/stat.h>

#include "mpi_driver/io/hdf5_file.hpp"

namespace blockfrag::hdf5 {
namespace {

// HDF5 casts between H5FD_t and this: `base` must come first.
struct TemporaryFile {
  H5FD_t base;
  int fd = -1;
  dev_t device = 0;
  ino_t inode = 0;
  haddr_t eoa = 0;
  haddr_t eof = 0;
  TemporaryFileState* state = nullptr;
};

TemporaryFile* as_file(H5FD_t* file) { return reinterpret_cast<TemporaryFile*>(file); }
const TemporaryFile* as_file(const H5FD_t* file) {
  return reinterpret_cast<const TemporaryFile*>(file);
}

// The failure as HDF5's own drivers word it ("error message = '...'"), on its error stack, where
// hdf5_handle.hpp's system_reason finds it.
void push_error(const char* what, const std::string& reason) {
  H5Epush2(H5E_DEFAULT, __FILE__, what, __LINE__, H5E_ERR_CLS, H5E_VFL, H5E_WRITEERROR,
           "error message = '%s'", reason.c_str());
}

// Records a failure; returns what the callback returns: an error the first time, unless the file
// is closing, and success once the file is given up.
herr_t give_up(TemporaryFile& file, const char* what) {
  const bool first = file.state->failure.empty();
  if (first) file.state->failure = std::strerror(errno);
  if (!first || file.state->closing) return 0;
  push_error(what, file.state->failure);
  return -1;
}

bool given_up(const TemporaryFile& file) { return !file.state->failure.empty(); }

H5FD_t* open_file(const char* name, unsigned flags, hid_t access, haddr_t) {
  const void* info = H5Pget_driver_info(access);
  if (!info) return nullptr;
  int mode = (flags & H5F_ACC_RDWR) ? O_RDWR : O_RDONLY;
  if (flags & H5F_ACC_CREAT) mode |= O_CREAT;
  if (flags & H5F_ACC_EXCL) mode |= O_EXCL;
  if (flags & H5F_ACC_TRUNC) mode |= O_TRUNC;
  const int fd = ::open(name, mode | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd < 0) {
    push_error("open", std::strerror(errno));
    return nullptr;
  }
  struct stat status {};
  if (::fstat(fd, &status) != 0) {
    push_error("open", std::strerror(errno));
    ::close(fd);
    return nullptr;
  }
  auto* file = new (std::nothrow) TemporaryFile{};
  if (!file) {
    ::close(fd);
    return nullptr;
  }
  file->fd = fd;
  file->device = status.st_dev;
  file->inode = status.st_ino;
  file->eof = static_cast<haddr_t>(status.st_size);
  file->state = *static_cast<TemporaryFileState* const*>(info);
  return &file->base;
}

// Always succeeds: a failed close would leave HDF5's file half torn down (the header says why).
herr_t close_file(H5FD_t* base) {
  TemporaryFile* file = as_file(base);
  if (::close(file->fd) != 0 && file->state->failure.empty()) {
    file->state->failure = std::strerror(errno);
  }
  delete file;
  return 0;
}

int compare_files(const H5FD_t* first, const H5FD_t* second) {
  const TemporaryFile* a = as_file(first);
  const TemporaryFile* b = as_file(second);
  if (a->device != b->device) return a->device < b->device ? -1 : 1;
  if (a->inode != b->inode) return a->inode < b->inode ? -1 : 1;
  return 0;
}

herr_t query_features(const H5FD_t*, unsigned long* flags) {
  *flags = H5FD_FEAT_AGGREGATE_METADATA | H5FD_FEAT_ACCUMULATE_METADATA | H5FD_FEAT_DATA_SIEVE |
           H5FD_FEAT_AGGREGATE_SMALLDATA | H5FD_FEAT_POSIX_COMPAT_HANDLE;
  return 0;
}

haddr_t get_eoa(const H5FD_t* file, H5FD_mem_t) { return as_file(file)->eoa; }

herr_t set_eoa(H5FD_t* file, H5FD_mem_t, haddr_t address) {
  as_file(file)->eoa = address;
  return 0;
}

haddr_t get_eof(const H5FD_t* file, H5FD_mem_t) { return as_file(file)->eof; }

herr_t get_handle(H5FD_t* file, hid_t, void** handle) {
  *handle = &as_file(file)->fd;
  return 0;
}

herr_t read_file(H5FD_t* base, H5FD_mem_t, hid_t, haddr_t address, size_t size, void* buffer) {
  TemporaryFile* file = as_file(base);
  char* bytes = static_cast<char*>(buffer);
  while (size > 0 && !given_up(*file)) {
    const ssize_t got = ::pread(file->fd, bytes, size, static_cast<off_t>(address));
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) return give_up(*file, "read");
    if (got == 0) break;  // past the end of the file: zeros
    bytes += got;
    size -= static_cast<size_t>(got);
    address += static_cast<haddr_t>(got);
  }
  std::memset(bytes, 0, size);
  return 0;
}

herr_t write_file(H5FD_t* base, H5FD_mem_t, hid_t, haddr_t address, size_t size,
                  const void* buffer) {
  TemporaryFile* file = as_file(base);
  const char* bytes = static_cast<const char*>(buffer);
  while (size > 0 && !given_up(*file)) {
    const ssize_t wrote = ::pwrite(file->fd, bytes, size, static_cast<off_t>(address));
    if (wrote < 0 && errno == EINTR) continue;
    if (wrote <= 0) {
      if (wrote == 0) errno = ENOSPC;
      return give_up(*file, "write");
    }
    bytes += wrote;
    size -= static_cast<size_t>(wrote);
    address += static_cast<haddr_t>(wrote);
    if (address > file->eof) file->eof = address;
  }
  return 0;
}

herr_t truncate_file(H5FD_t* base, hid_t, hbool_t) {
  TemporaryFile* file = as_file(base);
  if (given_up(*file) || file->eoa == file->eof) return 0;
  if (::ftruncate(file->fd, static_cast<off_t>(file->eoa)) != 0) return give_up(*file, "truncate");
  file->eof = file->eoa;
  return 0;
}

H5FD_class_t driver_class() {
  H5FD_class_t driver{};
  driver.name = "blockfrag_temporary";
  driver.maxaddr = (static_cast<haddr_t>(1) << (8 * sizeof(off_t) - 1)) - 1;
  driver.fc_degree = H5F_CLOSE_WEAK;
  driver.fapl_size = sizeof(TemporaryFileState*);
  driver.open = open_file;
  driver.close = close_file;
  driver.cmp = compare_files;
  driver.query = query_features;
  driver.get_eoa = get_eoa;
  driver.set_eoa = set_eoa;
  driver.get_eof = get_eof;
  driver.get_handle = get_handle;
  driver.read = read_file;
  driver.write = write_file;
  driver.truncate = truncate_file;
  const H5FD_mem_t map[H5FD_MEM_NTYPES] = H5FD_FLMAP_DICHOTOMY;
  std::copy(std::begin(map), std::end(map), driver.fl_map);
  return driver;
}

// Registered once per life of the library (MPI_Finalize ends it, and an identifier with it).
hid_t driver_id() {
  static const H5FD_class_t driver = driver_class();
  static hid_t id = -1;
  if (id < 0 || H5Iis_valid(id) <= 0) id = H5FDregister(&driver);
  if (id < 0) throw Hdf5Error("HDF5: cannot register the temporary files' driver");
  return id;
}

}  // namespace

hid_t temporary_file_access(TemporaryFileState* state) {
  const hid_t access = H5Pcreate(H5P_FILE_ACCESS);
  if (access < 0) throw Hdf5Error("HDF5: cannot create file access properties");
  if (H5Pset_driver(access, driver_id(), &state) < 0) {
    H5Pclose(access);
    throw Hdf5Error("HDF5: cannot set the temporary files' driver");
  }
  return access;
}

}  // namespace blockfrag::hdf5
