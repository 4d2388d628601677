// The HDF5 file driver of the outputs' temporary files: plain pread and pwrite on a descriptor,
// as HDF5's default driver (sec2), but a write or truncation that fails gives the file up.
//
// HDF5 leaves a file whose close failed half torn down, and closes it again when the library
// ends, inside MPI_Finalize, where it crashes: a full disk during an output's last write
// (ENOSPC, or EFBIG past a file size limit) made the program die of a segmentation fault with no
// message. With this driver the first failure is reported as the HDF5 call's error and recorded;
// after it every read, write and truncation succeeds without touching the file, so the file
// closes and the writer reports the recorded failure. The file's content is then lost, which is
// right: it is a temporary file, which the failed writer removes (atomic_file.hpp).
#pragma once

#include <hdf5.h>

#include <string>

namespace blockfrag::hdf5 {

// Shared by the driver and the writer of one file, for as long as the file is open.
struct TemporaryFileState {
  std::string failure;   // why the first write or truncation failed ("No space left on device")
  bool closing = false;  // set before H5Fclose: a failure then is recorded, not returned, so
                         // that the close succeeds
};

// A new file access property list (close it with H5Pclose) that opens files with this driver,
// tied to `state`, which must outlive the file.
hid_t temporary_file_access(TemporaryFileState* state);

}  // namespace blockfrag::hdf5
