// A small read-only view of an HDF5 file over the C API, for what reading a study's output back
// needs: which objects and attributes exist, string and numeric attributes (scalar or 1-D), 1-D
// numeric datasets and a group's members. Handles are closed by RAII. The file is a user's input
// and may be anything: every failure is an Hdf5ReadError naming the file and the object, every
// object is reached through hard links only (a soft, external or user-defined link could lead out
// of the file, to a FIFO that blocks forever or a device), no dataset's values may lie outside
// the file (external storage, a virtual dataset), no filter plugin is loaded (a library the file
// would choose), and every read states the most elements it accepts, checked against the extent
// the file declares before any memory is allocated. Whether the content makes sense (a blockfrag
// output, its schema) is the caller's business.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/errors.hpp"

namespace blockfrag {

// A file HDF5 cannot open or read, or whose objects are not what was asked for: the user's input,
// not the machine's fault (exit code 2). what() names the file.
class Hdf5ReadError : public InvalidInput {
 public:
  using InvalidInput::InvalidInput;
};

class Hdf5Reader {
 public:
  // Opens the file read-only; throws Hdf5ReadError when HDF5 cannot open it (truncated, damaged).
  explicit Hdf5Reader(const std::filesystem::path& path);
  ~Hdf5Reader();
  Hdf5Reader(const Hdf5Reader&) = delete;
  Hdf5Reader& operator=(const Hdf5Reader&) = delete;

  // Whether HDF5 recognises the file as HDF5 (its signature); false for anything else, a missing
  // or unreadable file included.
  static bool is_hdf5(const std::filesystem::path& path);

  // Absolute paths ("/fragility/overturn"); "/" is the file. Throws Hdf5ReadError when a link on
  // the way is not a hard link.
  bool has_object(const std::string& path) const;
  bool is_group(const std::string& path) const;
  bool has_attribute(const std::string& object, const std::string& name) const;

  // A string attribute, variable- or fixed-length (h5py writes either), of at most max_length
  // bytes; Hdf5ReadError when the attribute is missing, is not a single string or is longer.
  std::string string_attribute(const std::string& object, const std::string& name,
                               std::size_t max_length) const;
  // A numeric (float or integer) attribute holding exactly one value.
  double number_attribute(const std::string& object, const std::string& name) const;
  // A numeric attribute, scalar or 1-D, of at most max_count values: all its values.
  std::vector<double> number_array_attribute(const std::string& object, const std::string& name,
                                             std::size_t max_count) const;
  // A numeric 1-D (or scalar) dataset of at most max_count values, as doubles.
  std::vector<double> number_dataset(const std::string& path, std::size_t max_count) const;
  // The names of a group's members, in HDF5's name order.
  std::vector<std::string> member_names(const std::string& group) const;

  const std::string& name() const { return name_; }

 private:
  // The object at path, whose every link from the root is a hard one; Hdf5ReadError otherwise.
  void require_object(const std::string& path) const;
  Hdf5ReadError error(const std::string& what) const;

  std::int64_t file_ = -1;  // hid_t
  std::string name_;
};

}  // namespace blockfrag
