#include "mpi_driver/io/hdf5_reader.hpp"

#include <hdf5.h>

#include <type_traits>

#include "mpi_driver/io/hdf5_handle.hpp"

namespace blockfrag {
namespace {

static_assert(std::is_same_v<hid_t, std::int64_t>, "hid_t is stored as std::int64_t in the header");

using hdf5::check;
using hdf5::Handle;

// The number of elements of a scalar or 1-D dataspace; throws for anything of higher rank.
std::size_t element_count(hid_t space, const std::string& what) {
  const int rank = H5Sget_simple_extent_ndims(space);
  if (rank < 0) throw Hdf5Error("HDF5: cannot read the shape of " + what);
  if (rank > 1) throw Hdf5Error(what + " has " + std::to_string(rank) + " dimensions, not 1");
  const hssize_t count = H5Sget_simple_extent_npoints(space);
  if (count < 0) throw Hdf5Error("HDF5: cannot read the size of " + what);
  return static_cast<std::size_t>(count);
}

bool numeric(hid_t type) {
  const H5T_class_t type_class = H5Tget_class(type);
  return type_class == H5T_FLOAT || type_class == H5T_INTEGER;
}

}  // namespace

Hdf5Reader::Hdf5Reader(const std::filesystem::path& path) : name_(path.string()) {
  hdf5::silence_error_printing();
  file_ = H5Fopen(name_.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file_ < 0) throw Hdf5Error("HDF5: cannot open " + name_);
}

Hdf5Reader::~Hdf5Reader() {
  if (file_ >= 0) H5Fclose(file_);
}

bool Hdf5Reader::is_hdf5(const std::filesystem::path& path) {
  hdf5::silence_error_printing();
  return H5Fis_hdf5(path.c_str()) > 0;
}

bool Hdf5Reader::has_object(const std::string& path) const {
  if (path == "/") return true;
  if (path.empty() || path.front() != '/') return false;
  // H5Lexists needs every intermediate link to exist: walk the path one member at a time.
  std::size_t end = 0;
  while (end != std::string::npos) {
    end = path.find('/', end + 1);
    const std::string prefix = path.substr(0, end);
    if (H5Lexists(file_, prefix.c_str(), H5P_DEFAULT) <= 0) return false;
  }
  // A link may dangle: the object itself must be there.
  return H5Oexists_by_name(file_, path.c_str(), H5P_DEFAULT) > 0;
}

bool Hdf5Reader::is_group(const std::string& path) const {
  if (!has_object(path)) return false;
  Handle object(H5Oopen(file_, path.c_str(), H5P_DEFAULT), H5Oclose, "open " + path);
  return H5Iget_type(object.get()) == H5I_GROUP;
}

bool Hdf5Reader::has_attribute(const std::string& object, const std::string& name) const {
  if (!has_object(object)) return false;
  return H5Aexists_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT) > 0;
}

std::string Hdf5Reader::string_attribute(const std::string& object, const std::string& name) const {
  const std::string what = "attribute " + name + " of " + object + " in " + name_;
  Handle attribute(H5Aopen_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT),
                   H5Aclose, "open " + what);
  Handle type(H5Aget_type(attribute.get()), H5Tclose, "read the type of " + what);
  if (H5Tget_class(type.get()) != H5T_STRING) throw Hdf5Error(what + " is not a string");
  Handle space(H5Aget_space(attribute.get()), H5Sclose, "read the shape of " + what);
  if (element_count(space.get(), what) != 1) throw Hdf5Error(what + " is not a single string");
  const htri_t variable = H5Tis_variable_str(type.get());
  check(variable, "read the type of " + what);
  if (variable > 0) {
    Handle memory(H5Tcopy(H5T_C_S1), H5Tclose, "copy the string type");
    check(H5Tset_size(memory.get(), H5T_VARIABLE), "make a variable-length string type");
    check(H5Tset_cset(memory.get(), H5Tget_cset(type.get())), "set a string type's encoding");
    char* text = nullptr;
    check(H5Aread(attribute.get(), memory.get(), &text), "read " + what);
    std::string value = text ? text : "";
    H5free_memory(text);
    return value;
  }
  const std::size_t size = H5Tget_size(type.get());
  if (size == 0) throw Hdf5Error("HDF5: cannot read the size of " + what);
  Handle memory(H5Tcopy(H5T_C_S1), H5Tclose, "copy the string type");
  check(H5Tset_size(memory.get(), size), "make a fixed-length string type");
  check(H5Tset_cset(memory.get(), H5Tget_cset(type.get())), "set a string type's encoding");
  std::string buffer(size, '\0');
  check(H5Aread(attribute.get(), memory.get(), buffer.data()), "read " + what);
  return buffer.substr(0, buffer.find('\0'));
}

std::vector<double> Hdf5Reader::number_array_attribute(const std::string& object,
                                                       const std::string& name) const {
  const std::string what = "attribute " + name + " of " + object + " in " + name_;
  Handle attribute(H5Aopen_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT),
                   H5Aclose, "open " + what);
  Handle type(H5Aget_type(attribute.get()), H5Tclose, "read the type of " + what);
  if (!numeric(type.get())) throw Hdf5Error(what + " is not a number");
  Handle space(H5Aget_space(attribute.get()), H5Sclose, "read the shape of " + what);
  std::vector<double> values(element_count(space.get(), what));
  if (!values.empty()) {
    check(H5Aread(attribute.get(), H5T_NATIVE_DOUBLE, values.data()), "read " + what);
  }
  return values;
}

double Hdf5Reader::number_attribute(const std::string& object, const std::string& name) const {
  const auto values = number_array_attribute(object, name);
  if (values.size() != 1) {
    throw Hdf5Error("attribute " + name + " of " + object + " in " + name_ + " holds " +
                    std::to_string(values.size()) + " values, not 1");
  }
  return values.front();
}

std::vector<double> Hdf5Reader::number_dataset(const std::string& path) const {
  const std::string what = "dataset " + path + " in " + name_;
  Handle dataset(H5Dopen2(file_, path.c_str(), H5P_DEFAULT), H5Dclose, "open " + what);
  Handle type(H5Dget_type(dataset.get()), H5Tclose, "read the type of " + what);
  if (!numeric(type.get())) throw Hdf5Error(what + " does not hold numbers");
  Handle space(H5Dget_space(dataset.get()), H5Sclose, "read the shape of " + what);
  std::vector<double> values(element_count(space.get(), what));
  if (!values.empty()) {
    check(H5Dread(dataset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()),
          "read " + what);
  }
  return values;
}

std::vector<std::string> Hdf5Reader::member_names(const std::string& group) const {
  const std::string what = "group " + group + " in " + name_;
  Handle handle(H5Gopen2(file_, group.c_str(), H5P_DEFAULT), H5Gclose, "open " + what);
  H5G_info_t info{};
  check(H5Gget_info(handle.get(), &info), "read " + what);
  std::vector<std::string> names;
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t length = H5Lget_name_by_idx(handle.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i,
                                              nullptr, 0, H5P_DEFAULT);
    if (length < 0) throw Hdf5Error("HDF5: cannot read the members of " + what);
    std::string name(static_cast<std::size_t>(length) + 1, '\0');
    check(static_cast<herr_t>(H5Lget_name_by_idx(handle.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i,
                                                 name.data(), name.size(), H5P_DEFAULT) < 0
                                  ? -1
                                  : 0),
          "read the members of " + what);
    name.resize(static_cast<std::size_t>(length));
    names.push_back(std::move(name));
  }
  return names;
}

}  // namespace blockfrag
