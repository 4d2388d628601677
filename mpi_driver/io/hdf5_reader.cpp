#include "mpi_driver/io/hdf5_reader.hpp"

#include <hdf5.h>

#include <type_traits>

#include "mpi_driver/config/input_file.hpp"
#include "mpi_driver/io/hdf5_handle.hpp"

namespace blockfrag {
namespace {

static_assert(std::is_same_v<hid_t, std::int64_t>, "hid_t is stored as std::int64_t in the header");

using hdf5::Handle;

// A path or name the caller built from the file's own link names, which may hold anything.
std::string shown(const std::string& text) { return printable_excerpt(text, 120); }

// A handle, or the error when HDF5 could not give one.
Handle opened(hid_t id, herr_t (*close)(hid_t), const Hdf5ReadError& error) {
  if (id < 0) throw error;
  return Handle(id, close, "");
}

void require(herr_t status, const Hdf5ReadError& error) {
  if (status < 0) throw error;
}

// One of HDF5's standard integer or IEEE float types. HDF5 converts any integer or float layout the
// file describes, and its conversion of a malformed one (a precision or offset past the type's
// size) reads outside its buffers: only the layouts writers use are read.
bool numeric(hid_t type) {
  for (const hid_t standard :
       {H5T_IEEE_F64LE, H5T_IEEE_F64BE, H5T_IEEE_F32LE, H5T_IEEE_F32BE, H5T_STD_I64LE,
        H5T_STD_I64BE,  H5T_STD_I32LE,  H5T_STD_I32BE,  H5T_STD_I16LE,  H5T_STD_I16BE,
        H5T_STD_I8LE,   H5T_STD_I8BE,   H5T_STD_U64LE,  H5T_STD_U64BE,  H5T_STD_U32LE,
        H5T_STD_U32BE,  H5T_STD_U16LE,  H5T_STD_U16BE,  H5T_STD_U8LE,   H5T_STD_U8BE}) {
    if (H5Tequal(type, standard) > 0) return true;
  }
  return false;
}

const char* link_kind(H5L_type_t type) {
  switch (type) {
    case H5L_TYPE_SOFT: return "a soft link";
    case H5L_TYPE_EXTERNAL: return "an external link";
    default: return "a user-defined link";
  }
}

}  // namespace

Hdf5Reader::Hdf5Reader(const std::filesystem::path& path) : name_(path.string()) {
  hdf5::silence_error_printing();
  // A filter plugin is a shared library HDF5 would load because the file names its filter.
  H5PLset_loading_state(0);
  file_ = H5Fopen(name_.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file_ < 0) {
    throw error("HDF5 cannot open it (a truncated or damaged file), so it cannot be read");
  }
}

Hdf5Reader::~Hdf5Reader() {
  if (file_ >= 0) H5Fclose(file_);
}

Hdf5ReadError Hdf5Reader::error(const std::string& what) const {
  return Hdf5ReadError(name_ + ": " + what);
}

bool Hdf5Reader::is_hdf5(const std::filesystem::path& path) {
  hdf5::silence_error_printing();
  return H5Fis_hdf5(path.c_str()) > 0;
}

bool Hdf5Reader::has_object(const std::string& path) const {
  if (path == "/") return true;
  if (path.empty() || path.front() != '/') return false;
  // Each link is examined before anything follows it: H5Lexists and H5Lget_info look at the last
  // link of their path without traversing it, and every link before it is hard.
  std::size_t end = 0;
  while (end != std::string::npos) {
    end = path.find('/', end + 1);
    const std::string prefix = path.substr(0, end);
    if (H5Lexists(file_, prefix.c_str(), H5P_DEFAULT) <= 0) return false;
    H5L_info_t link{};
    require(H5Lget_info(file_, prefix.c_str(), &link, H5P_DEFAULT),
            error("HDF5 cannot read the link " + shown(prefix)));
    if (link.type != H5L_TYPE_HARD) {
      throw error(shown(prefix) + " is " + link_kind(link.type) +
                  ": blockfrag reads only objects inside the file, linked as it writes them");
    }
  }
  return H5Oexists_by_name(file_, path.c_str(), H5P_DEFAULT) > 0;
}

void Hdf5Reader::require_object(const std::string& path) const {
  if (!has_object(path)) throw error(shown(path) + " is missing");
}

bool Hdf5Reader::is_group(const std::string& path) const {
  if (!has_object(path)) return false;
  const Handle object = opened(H5Oopen(file_, path.c_str(), H5P_DEFAULT), H5Oclose,
                               error("HDF5 cannot open " + shown(path)));
  return H5Iget_type(object.get()) == H5I_GROUP;
}

bool Hdf5Reader::has_attribute(const std::string& object, const std::string& name) const {
  if (!has_object(object)) return false;
  return H5Aexists_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT) > 0;
}

namespace {

// The number of elements of a scalar or 1-D dataspace, at most max_count.
std::size_t element_count(hid_t space, std::size_t max_count, const std::string& what,
                          const std::string& file) {
  const int rank = H5Sget_simple_extent_ndims(space);
  if (rank < 0) throw Hdf5ReadError(file + ": HDF5 cannot read the shape of " + what);
  if (rank > 1) {
    throw Hdf5ReadError(file + ": " + what + " has " + std::to_string(rank) + " dimensions, not 1");
  }
  const hssize_t count = H5Sget_simple_extent_npoints(space);
  if (count < 0) throw Hdf5ReadError(file + ": HDF5 cannot read the size of " + what);
  if (static_cast<std::size_t>(count) > max_count) {
    throw Hdf5ReadError(file + ": " + what + " holds " + std::to_string(count) +
                        " values, more than the " + std::to_string(max_count) +
                        " a blockfrag study output has there");
  }
  return static_cast<std::size_t>(count);
}

}  // namespace

std::string Hdf5Reader::string_attribute(const std::string& object, const std::string& name,
                                         std::size_t max_length) const {
  require_object(object);
  const std::string what = "attribute " + shown(name) + " of " + shown(object);
  const auto cannot = [&](const std::string& action) {
    return error("HDF5 cannot " + action + " " + what);
  };
  const Handle attribute =
      opened(H5Aopen_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT),
             H5Aclose, cannot("open"));
  const Handle type = opened(H5Aget_type(attribute.get()), H5Tclose, cannot("read the type of"));
  if (H5Tget_class(type.get()) != H5T_STRING) throw error(what + " is not a string");
  const Handle space = opened(H5Aget_space(attribute.get()), H5Sclose, cannot("read the shape of"));
  if (element_count(space.get(), 1, what, name_) != 1) throw error(what + " is not one string");
  const htri_t variable = H5Tis_variable_str(type.get());
  require(variable, cannot("read the type of"));
  const H5T_cset_t encoding = H5Tget_cset(type.get());
  std::string value;
  if (variable > 0) {
    const Handle memory = opened(H5Tcopy(H5T_C_S1), H5Tclose, cannot("copy the type of"));
    require(H5Tset_size(memory.get(), H5T_VARIABLE), cannot("make the type of"));
    require(H5Tset_cset(memory.get(), encoding), cannot("read the encoding of"));
    char* text = nullptr;
    require(H5Aread(attribute.get(), memory.get(), &text), cannot("read"));
    value = text ? text : "";
    H5free_memory(text);
  } else {
    const std::size_t size = H5Tget_size(type.get());
    if (size == 0) throw cannot("read the size of");
    // A fixed-length string may carry its terminating NUL.
    if (size > max_length + 1) {
      throw error(what + " is " + std::to_string(size) + " bytes long, more than " +
                  std::to_string(max_length));
    }
    const Handle memory = opened(H5Tcopy(H5T_C_S1), H5Tclose, cannot("copy the type of"));
    require(H5Tset_size(memory.get(), size), cannot("make the type of"));
    require(H5Tset_cset(memory.get(), encoding), cannot("read the encoding of"));
    std::string buffer(size, '\0');
    require(H5Aread(attribute.get(), memory.get(), buffer.data()), cannot("read"));
    value = buffer.substr(0, buffer.find('\0'));
  }
  if (value.size() > max_length) {
    throw error(what + " is " + std::to_string(value.size()) + " bytes long, more than " +
                std::to_string(max_length) + " (\"" + printable_excerpt(value) + "\")");
  }
  return value;
}

std::vector<double> Hdf5Reader::number_array_attribute(const std::string& object,
                                                       const std::string& name,
                                                       std::size_t max_count) const {
  require_object(object);
  const std::string what = "attribute " + shown(name) + " of " + shown(object);
  const auto cannot = [&](const std::string& action) {
    return error("HDF5 cannot " + action + " " + what);
  };
  const Handle attribute =
      opened(H5Aopen_by_name(file_, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT),
             H5Aclose, cannot("open"));
  const Handle type = opened(H5Aget_type(attribute.get()), H5Tclose, cannot("read the type of"));
  if (!numeric(type.get())) throw error(what + " is not a number");
  const Handle space = opened(H5Aget_space(attribute.get()), H5Sclose, cannot("read the shape of"));
  std::vector<double> values(element_count(space.get(), max_count, what, name_));
  if (!values.empty()) {
    require(H5Aread(attribute.get(), H5T_NATIVE_DOUBLE, values.data()), cannot("read"));
  }
  return values;
}

double Hdf5Reader::number_attribute(const std::string& object, const std::string& name) const {
  const auto values = number_array_attribute(object, name, 1);
  if (values.size() != 1) {
    throw error("attribute " + shown(name) + " of " + shown(object) + " holds no value");
  }
  return values.front();
}

std::vector<double> Hdf5Reader::number_dataset(const std::string& path,
                                               std::size_t max_count) const {
  require_object(path);
  const std::string what = "dataset " + shown(path);
  const auto cannot = [&](const std::string& action) {
    return error("HDF5 cannot " + action + " " + what);
  };
  const Handle dataset =
      opened(H5Dopen2(file_, path.c_str(), H5P_DEFAULT), H5Dclose, cannot("open"));
  const Handle type = opened(H5Dget_type(dataset.get()), H5Tclose, cannot("read the type of"));
  if (!numeric(type.get())) throw error(what + " does not hold numbers");
  const Handle space = opened(H5Dget_space(dataset.get()), H5Sclose, cannot("read the shape of"));
  std::vector<double> values(element_count(space.get(), max_count, what, name_));
  const Handle creation =
      opened(H5Dget_create_plist(dataset.get()), H5Pclose, cannot("read the layout of"));
  const H5D_layout_t layout = H5Pget_layout(creation.get());
  if (layout < 0) throw cannot("read the layout of");
  if (layout == H5D_VIRTUAL || H5Pget_external_count(creation.get()) != 0) {
    throw error(what +
                " keeps its values in other files: blockfrag reads only values inside the "
                "file");
  }
  if (!values.empty()) {
    require(H5Dread(dataset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()),
            cannot("read"));
  }
  return values;
}

std::vector<std::string> Hdf5Reader::member_names(const std::string& group) const {
  require_object(group);
  const std::string what = "the members of " + shown(group);
  const Handle handle = opened(H5Gopen2(file_, group.c_str(), H5P_DEFAULT), H5Gclose,
                               error("HDF5 cannot open the group " + shown(group)));
  H5G_info_t info{};
  require(H5Gget_info(handle.get(), &info), error("HDF5 cannot read " + what));
  std::vector<std::string> names;
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t length = H5Lget_name_by_idx(handle.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i,
                                              nullptr, 0, H5P_DEFAULT);
    if (length < 0) throw error("HDF5 cannot read " + what);
    std::string name(static_cast<std::size_t>(length) + 1, '\0');
    if (H5Lget_name_by_idx(handle.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(),
                           name.size(), H5P_DEFAULT) < 0) {
      throw error("HDF5 cannot read " + what);
    }
    name.resize(static_cast<std::size_t>(length));
    names.push_back(std::move(name));
  }
  return names;
}

}  // namespace blockfrag
