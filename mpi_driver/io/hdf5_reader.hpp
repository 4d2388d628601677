// A small read-only view of an HDF5 file over the C API, for what reading a study's output back
// needs: which objects and attributes exist, string and numeric attributes (scalar or 1-D), 1-D
// numeric datasets and a group's members. Handles are closed by RAII; a failed call throws
// Hdf5Error naming the file and the object. Whether the content makes sense (a blockfrag output,
// its schema) is the caller's business.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "mpi_driver/io/hdf5_file.hpp"

namespace blockfrag {

class Hdf5Reader {
 public:
  // Opens the file read-only; throws Hdf5Error when HDF5 cannot open it.
  explicit Hdf5Reader(const std::filesystem::path& path);
  ~Hdf5Reader();
  Hdf5Reader(const Hdf5Reader&) = delete;
  Hdf5Reader& operator=(const Hdf5Reader&) = delete;

  // Whether HDF5 recognises the file as HDF5 (its signature); false for anything else, a missing
  // or unreadable file included.
  static bool is_hdf5(const std::filesystem::path& path);

  // Absolute paths ("/fragility/overturn"); "/" is the file.
  bool has_object(const std::string& path) const;
  bool is_group(const std::string& path) const;
  bool has_attribute(const std::string& object, const std::string& name) const;

  // A string attribute, variable- or fixed-length (h5py writes either); Hdf5Error when the
  // attribute is missing or is not a single string.
  std::string string_attribute(const std::string& object, const std::string& name) const;
  // A numeric (float or integer) attribute holding exactly one value.
  double number_attribute(const std::string& object, const std::string& name) const;
  // A numeric attribute, scalar or 1-D: all its values.
  std::vector<double> number_array_attribute(const std::string& object,
                                             const std::string& name) const;
  // A numeric 1-D (or scalar) dataset's values as doubles.
  std::vector<double> number_dataset(const std::string& path) const;
  // The names of a group's members, in HDF5's name order.
  std::vector<std::string> member_names(const std::string& group) const;

  const std::string& name() const { return name_; }

 private:
  std::int64_t file_ = -1;  // hid_t
  std::string name_;
};

}  // namespace blockfrag
