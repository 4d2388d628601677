// A small writer over the HDF5 C API for what the outputs need: groups, 1-D columns (whole, or in
// parts for columns longer than memory), 2-D matrices and attributes. Handles are closed by RAII;
// every failed call throws Hdf5Error naming the object. Object modification times are not recorded,
// so the file's content depends only on what is written.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "engine/errors.hpp"

namespace blockfrag {

namespace hdf5 {
struct TemporaryFileState;
}

class Hdf5Error : public FileFailure {
 public:
  using FileFailure::FileFailure;
};

class Hdf5Writer {
 public:
  enum class ColumnType { float64, int64 };

  // Creates the file, which must not exist yet (exclusive: a link or file there is an error).
  explicit Hdf5Writer(const std::filesystem::path& path);
  ~Hdf5Writer();
  Hdf5Writer(const Hdf5Writer&) = delete;
  Hdf5Writer& operator=(const Hdf5Writer&) = delete;

  // Absolute paths ("/fragility/overturn"); the parent must exist.
  void create_group(const std::string& path);
  void write_column(const std::string& path, const std::vector<double>& values);
  void write_column(const std::string& path, const std::vector<std::int64_t>& values);
  // A column of `size` entries too long to hold at once: created empty, then filled in parts.
  void create_column(const std::string& path, std::int64_t size, ColumnType type);
  void write_part(const std::string& path, std::int64_t offset, std::span<const double> values);
  void write_part(const std::string& path, std::int64_t offset,
                  std::span<const std::int64_t> values);
  // A 2-D dataset of rows x columns, the values row by row (h5py reads it as that shape).
  void write_matrix(const std::string& path, std::int64_t rows, std::int64_t columns,
                    const std::vector<double>& values);
  void write_matrix(const std::string& path, std::int64_t rows, std::int64_t columns,
                    const std::vector<std::int64_t>& values);
  // Variable-length UTF-8 strings (h5py reads them as bytes, .asstr() as str).
  void write_column(const std::string& path, const std::vector<std::string>& values);

  // Attributes on an existing object ("/" for the file).
  void set_attribute(const std::string& object, const std::string& name, const std::string& value);
  void set_attribute(const std::string& object, const std::string& name, double value);
  void set_attribute(const std::string& object, const std::string& name, std::int64_t value);
  // A 1-D array attribute (h5py reads it as a numpy array).
  void set_attribute(const std::string& object, const std::string& name,
                     const std::vector<double>& values);

  // Flushes and closes, and throws Hdf5Error if any write failed; the destructor closes too but
  // cannot report a failure. Either close succeeds even on a full disk, which gives up the file's
  // content (mpi_driver/io/hdf5_temporary_driver.hpp): HDF5 is left holding no file.
  void close();

 private:
  std::int64_t file_ = -1;  // hid_t
  std::string name_;
  std::unique_ptr<hdf5::TemporaryFileState> state_;  // the file's driver's, at a fixed address
};

// The variable-length UTF-8 string attribute `name` of the file's root (h5py reads it as str);
// throws Hdf5Error when the file or the attribute is missing.
std::string read_root_string_attribute(const std::filesystem::path& path, const std::string& name);

}  // namespace blockfrag
