#include "mpi_driver/io/hdf5_file.hpp"

#include <hdf5.h>

#include <type_traits>

#include "mpi_driver/io/hdf5_handle.hpp"
#include "mpi_driver/io/hdf5_temporary_driver.hpp"

namespace blockfrag {
namespace {

static_assert(std::is_same_v<hid_t, std::int64_t>, "hid_t is stored as std::int64_t in the header");

using hdf5::check;
using hdf5::Handle;

Handle creation_properties(hid_t property_class, const std::string& what) {
  Handle properties(H5Pcreate(property_class), H5Pclose, "create properties for " + what);
  check(H5Pset_obj_track_times(properties.get(), false), "disable time tracking for " + what);
  return properties;
}

// A dataset of the given shape (1-D: one size), written whole.
template <typename T>
void write_typed_dataset(hid_t file, const std::string& path, const std::vector<hsize_t>& shape,
                         const std::vector<T>& values, hid_t file_type, hid_t memory_type) {
  Handle space(H5Screate_simple(static_cast<int>(shape.size()), shape.data(), nullptr), H5Sclose,
               "create a dataspace for " + path);
  const auto properties = creation_properties(H5P_DATASET_CREATE, path);
  Handle dataset(H5Dcreate2(file, path.c_str(), file_type, space.get(), H5P_DEFAULT,
                            properties.get(), H5P_DEFAULT),
                 H5Dclose, "create dataset " + path);
  if (!values.empty()) {
    check(H5Dwrite(dataset.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()),
          "write dataset " + path);
  }
}

template <typename T>
void write_typed_column(hid_t file, const std::string& path, const std::vector<T>& values,
                        hid_t file_type, hid_t memory_type) {
  write_typed_dataset(file, path, {values.size()}, values, file_type, memory_type);
}

template <typename T>
void write_typed_matrix(hid_t file, const std::string& path, std::int64_t rows,
                        std::int64_t columns, const std::vector<T>& values, hid_t file_type,
                        hid_t memory_type) {
  if (rows < 0 || columns < 0 || static_cast<std::size_t>(rows * columns) != values.size())
    throw ContractViolation("write_matrix: " + path + " needs rows x columns values");
  write_typed_dataset(file, path, {static_cast<hsize_t>(rows), static_cast<hsize_t>(columns)},
                      values, file_type, memory_type);
}

template <typename T>
void write_typed_part(hid_t file, const std::string& path, std::int64_t offset,
                      std::span<const T> values, hid_t memory_type) {
  if (values.empty()) return;
  Handle dataset(H5Dopen2(file, path.c_str(), H5P_DEFAULT), H5Dclose, "open dataset " + path);
  Handle file_space(H5Dget_space(dataset.get()), H5Sclose, "get the dataspace of " + path);
  const hsize_t start = static_cast<hsize_t>(offset), count = values.size();
  check(H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, &start, nullptr, &count, nullptr),
        "select a part of " + path);
  Handle memory_space(H5Screate_simple(1, &count, nullptr), H5Sclose,
                      "create a dataspace for a part of " + path);
  check(H5Dwrite(dataset.get(), memory_type, memory_space.get(), file_space.get(), H5P_DEFAULT,
                 values.data()),
        "write a part of " + path);
}

template <typename T>
void write_attribute(hid_t file, const std::string& object, const std::string& name, hid_t type,
                     const T* value) {
  const std::string what = "attribute " + name + " of " + object;
  Handle target(H5Oopen(file, object.c_str(), H5P_DEFAULT), H5Oclose, "open " + object);
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, "create a dataspace for " + what);
  Handle attribute(
      H5Acreate2(target.get(), name.c_str(), type, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
      "create " + what);
  check(H5Awrite(attribute.get(), type, value), "write " + what);
}

Handle utf8_string_type() {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "copy the string type");
  check(H5Tset_size(type.get(), H5T_VARIABLE), "make a variable-length string type");
  check(H5Tset_cset(type.get(), H5T_CSET_UTF8), "make a UTF-8 string type");
  return type;
}

}  // namespace

Hdf5Writer::Hdf5Writer(const std::filesystem::path& path)
    : name_(path.string()), state_(std::make_unique<hdf5::TemporaryFileState>()) {
  hdf5::silence_error_printing();
  const auto properties = creation_properties(H5P_FILE_CREATE, name_);
  const Handle access(hdf5::temporary_file_access(state_.get()), H5Pclose,
                      "create file access properties for " + name_);
  // Exclusive: the file must not exist (atomic_file.hpp gives a fresh name), so nothing planted
  // there, a link included, is ever opened.
  file_ = H5Fcreate(name_.c_str(), H5F_ACC_EXCL, properties.get(), access.get());
  if (file_ < 0) throw Hdf5Error("HDF5: cannot create " + name_ + hdf5::system_reason());
}

Hdf5Writer::~Hdf5Writer() {
  if (file_ < 0) return;
  state_->closing = true;
  H5Fclose(file_);
}

void Hdf5Writer::close() {
  if (file_ < 0) return;
  const hid_t file = file_;
  file_ = -1;
  // The flush reports a failure as an error; the close that follows then succeeds whatever
  // happens (hdf5_temporary_driver.hpp).
  const bool flushed = H5Fflush(file, H5F_SCOPE_LOCAL) >= 0;
  state_->closing = true;
  const bool closed = H5Fclose(file) >= 0;
  if (!state_->failure.empty()) {
    throw Hdf5Error("HDF5: cannot write " + name_ + " (" + state_->failure + ")");
  }
  if (!flushed || !closed) throw Hdf5Error("HDF5: cannot close " + name_);
}

void Hdf5Writer::create_group(const std::string& path) {
  const auto properties = creation_properties(H5P_GROUP_CREATE, path);
  Handle group(H5Gcreate2(file_, path.c_str(), H5P_DEFAULT, properties.get(), H5P_DEFAULT),
               H5Gclose, "create group " + path);
}

void Hdf5Writer::write_column(const std::string& path, const std::vector<double>& values) {
  write_typed_column(file_, path, values, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE);
}

void Hdf5Writer::write_column(const std::string& path, const std::vector<std::int64_t>& values) {
  write_typed_column(file_, path, values, H5T_STD_I64LE, H5T_NATIVE_INT64);
}

void Hdf5Writer::write_matrix(const std::string& path, std::int64_t rows, std::int64_t columns,
                              const std::vector<double>& values) {
  write_typed_matrix(file_, path, rows, columns, values, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE);
}

void Hdf5Writer::write_matrix(const std::string& path, std::int64_t rows, std::int64_t columns,
                              const std::vector<std::int64_t>& values) {
  write_typed_matrix(file_, path, rows, columns, values, H5T_STD_I64LE, H5T_NATIVE_INT64);
}

void Hdf5Writer::create_column(const std::string& path, std::int64_t size, ColumnType type) {
  const hsize_t length = static_cast<hsize_t>(size);
  Handle space(H5Screate_simple(1, &length, nullptr), H5Sclose, "create a dataspace for " + path);
  const auto properties = creation_properties(H5P_DATASET_CREATE, path);
  Handle dataset(
      H5Dcreate2(file_, path.c_str(), type == ColumnType::float64 ? H5T_IEEE_F64LE : H5T_STD_I64LE,
                 space.get(), H5P_DEFAULT, properties.get(), H5P_DEFAULT),
      H5Dclose, "create dataset " + path);
}

void Hdf5Writer::write_part(const std::string& path, std::int64_t offset,
                            std::span<const double> values) {
  write_typed_part(file_, path, offset, values, H5T_NATIVE_DOUBLE);
}

void Hdf5Writer::write_part(const std::string& path, std::int64_t offset,
                            std::span<const std::int64_t> values) {
  write_typed_part(file_, path, offset, values, H5T_NATIVE_INT64);
}

void Hdf5Writer::write_column(const std::string& path, const std::vector<std::string>& values) {
  const auto type = utf8_string_type();
  std::vector<const char*> texts;
  texts.reserve(values.size());
  for (const auto& value : values) texts.push_back(value.c_str());
  write_typed_column(file_, path, texts, type.get(), type.get());
}

void Hdf5Writer::set_attribute(const std::string& object, const std::string& name,
                               const std::string& value) {
  const auto type = utf8_string_type();
  const char* text = value.c_str();
  write_attribute(file_, object, name, type.get(), &text);
}

void Hdf5Writer::set_attribute(const std::string& object, const std::string& name, double value) {
  write_attribute(file_, object, name, H5T_NATIVE_DOUBLE, &value);
}

void Hdf5Writer::set_attribute(const std::string& object, const std::string& name,
                               std::int64_t value) {
  write_attribute(file_, object, name, H5T_NATIVE_INT64, &value);
}

void Hdf5Writer::set_attribute(const std::string& object, const std::string& name,
                               const std::vector<double>& values) {
  const std::string what = "attribute " + name + " of " + object;
  Handle target(H5Oopen(file_, object.c_str(), H5P_DEFAULT), H5Oclose, "open " + object);
  const hsize_t size = values.size();
  Handle space(H5Screate_simple(1, &size, nullptr), H5Sclose, "create a dataspace for " + what);
  Handle attribute(
      H5Acreate2(target.get(), name.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT),
      H5Aclose, "create " + what);
  check(H5Awrite(attribute.get(), H5T_NATIVE_DOUBLE, values.data()), "write " + what);
}

std::string read_root_string_attribute(const std::filesystem::path& path, const std::string& name) {
  hdf5::silence_error_printing();
  const std::string what = "attribute " + name + " of " + path.string();
  Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose,
              "open " + path.string());
  Handle attribute(H5Aopen(file.get(), name.c_str(), H5P_DEFAULT), H5Aclose, "open " + what);
  const auto type = utf8_string_type();
  char* text = nullptr;
  check(H5Aread(attribute.get(), type.get(), &text), "read " + what);
  std::string value = text ? text : "";
  H5free_memory(text);
  return value;
}

}  // namespace blockfrag
