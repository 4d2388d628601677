// Hdf5Reader on files that are not what they claim: links that leave the file (a FIFO behind an
// external link would block the open forever), values kept in other files, extents larger than
// the caller accepts (checked before anything is allocated), strings longer than asked for, and
// files HDF5 cannot open. Each is an Hdf5ReadError, an InvalidInput naming the file. The files are
// made with HDF5's C API, which can write what blockfrag's writer never does.
#include "mpi_driver/io/hdf5_reader.hpp"

#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <sys/stat.h>

#include "mpi_driver/io/hdf5_file.hpp"
#include "tests/support/temporary_folder.hpp"

namespace blockfrag {
namespace {

using testing::TemporaryFolder;

// Expects `call` to throw Hdf5ReadError whose message holds every fragment.
template <typename Call>
void expect_read_refused(Call call, const std::vector<std::string>& fragments) {
  try {
    call();
    ADD_FAILURE() << "no Hdf5ReadError";
  } catch (const Hdf5ReadError& error) {
    for (const auto& fragment : fragments) {
      EXPECT_NE(std::string(error.what()).find(fragment), std::string::npos)
          << "\"" << error.what() << "\" lacks \"" << fragment << "\"";
    }
  }
}

// A file with /g holding the dataset /g/values {1, 2, 3} and the string attribute /g's "text".
void write_base(const std::filesystem::path& path) {
  Hdf5Writer file(path);
  file.create_group("/g");
  file.set_attribute("/g", "text", std::string("twelve chars"));
  file.write_column("/g/values", std::vector<double>{1.0, 2.0, 3.0});
  file.close();
}

// Opens the file for writing with the C API, for what the project's writer does not make.
class RawFile {
 public:
  explicit RawFile(const std::filesystem::path& path)
      : id_(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT)) {
    if (id_ < 0) throw std::runtime_error("cannot open " + path.string());
  }
  ~RawFile() { H5Fclose(id_); }
  RawFile(const RawFile&) = delete;
  RawFile& operator=(const RawFile&) = delete;
  hid_t id() const { return id_; }

 private:
  hid_t id_;
};

TEST(Hdf5Reader, RefusesLinksThatAreNotHard) {
  TemporaryFolder folder;
  const auto path = folder.path() / "links.h5";
  write_base(path);
  const auto fifo = folder.path() / "ext.fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  {
    const RawFile raw(path);
    ASSERT_GE(
        H5Lcreate_external(fifo.c_str(), "/x", raw.id(), "/g/outside", H5P_DEFAULT, H5P_DEFAULT),
        0);
    ASSERT_GE(H5Lcreate_soft("/g", raw.id(), "/alias", H5P_DEFAULT, H5P_DEFAULT), 0);
  }
  const Hdf5Reader reader(path);
  // Nothing follows the external link: opening the FIFO would block this test forever.
  expect_read_refused([&] { reader.has_object("/g/outside"); },
                      {"links.h5", "/g/outside", "external link"});
  expect_read_refused([&] { reader.number_dataset("/g/outside/values", 10); },
                      {"links.h5", "external link"});
  expect_read_refused([&] { reader.is_group("/alias"); }, {"links.h5", "/alias", "soft link"});
  expect_read_refused([&] { reader.string_attribute("/alias", "text", 64); }, {"soft link"});
  EXPECT_TRUE(reader.has_object("/g/values"));
}

TEST(Hdf5Reader, RefusesValuesKeptInOtherFiles) {
  TemporaryFolder folder;
  const auto path = folder.path() / "external.h5";
  write_base(path);
  {
    const RawFile raw(path);
    const hsize_t extent = 4;
    const hid_t space = H5Screate_simple(1, &extent, nullptr);
    const hid_t creation = H5Pcreate(H5P_DATASET_CREATE);
    H5Pset_external(creation, (folder.path() / "raw.bin").c_str(), 0, 4 * sizeof(double));
    const hid_t dataset = H5Dcreate2(raw.id(), "/g/stored_elsewhere", H5T_IEEE_F64LE, space,
                                     H5P_DEFAULT, creation, H5P_DEFAULT);
    ASSERT_GE(dataset, 0);
    H5Dclose(dataset);
    H5Pclose(creation);
    H5Sclose(space);
  }
  const Hdf5Reader reader(path);
  expect_read_refused([&] { reader.number_dataset("/g/stored_elsewhere", 10); },
                      {"external.h5", "/g/stored_elsewhere", "in other files"});
}

TEST(Hdf5Reader, RefusesMoreThanTheCallerAccepts) {
  TemporaryFolder folder;
  const auto path = folder.path() / "extent.h5";
  write_base(path);
  {
    // 6e8 doubles declared, none stored: 4.8 GB if the reader believed the extent.
    const RawFile raw(path);
    const hsize_t extent = 600'000'000;
    const hid_t space = H5Screate_simple(1, &extent, nullptr);
    const hid_t dataset = H5Dcreate2(raw.id(), "/g/huge", H5T_IEEE_F64LE, space, H5P_DEFAULT,
                                     H5P_DEFAULT, H5P_DEFAULT);
    ASSERT_GE(dataset, 0);
    H5Dclose(dataset);
    H5Sclose(space);
  }
  const Hdf5Reader reader(path);
  expect_read_refused([&] { reader.number_dataset("/g/huge", 1000); },
                      {"extent.h5", "/g/huge", "600000000 values, more than the 1000"});
  expect_read_refused([&] { reader.number_dataset("/g/values", 2); }, {"3 values"});
  EXPECT_EQ(reader.number_dataset("/g/values", 3), (std::vector<double>{1.0, 2.0, 3.0}));
  expect_read_refused([&] { reader.string_attribute("/g", "text", 11); },
                      {"extent.h5", "attribute text of /g", "more than 11"});
  EXPECT_EQ(reader.string_attribute("/g", "text", 12), "twelve chars");
}

// HDF5 converts any integer layout a file describes to double, and reads outside its buffers for a
// malformed one (found by tests/fuzz/hdf5_reader_fuzzer.cpp): only standard layouts are read.
TEST(Hdf5Reader, ReadsOnlyStandardNumberTypes) {
  TemporaryFolder folder;
  const auto path = folder.path() / "types.h5";
  write_base(path);
  {
    const RawFile raw(path);
    const hid_t type = H5Tcopy(H5T_STD_I32LE);
    H5Tset_precision(type, 20);
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t attribute = H5Acreate_by_name(raw.id(), "/g", "odd", type, space, H5P_DEFAULT,
                                              H5P_DEFAULT, H5P_DEFAULT);
    ASSERT_GE(attribute, 0);
    const std::int32_t value = 5;
    H5Awrite(attribute, H5T_NATIVE_INT32, &value);
    H5Aclose(attribute);
    H5Sclose(space);
    H5Tclose(type);
  }
  const Hdf5Reader reader(path);
  expect_read_refused([&] { reader.number_attribute("/g", "odd"); },
                      {"types.h5", "attribute odd of /g is not a number"});
}

TEST(Hdf5Reader, RefusesFilesHdf5CannotOpen) {
  TemporaryFolder folder;
  const auto path = folder.path() / "whole.h5";
  write_base(path);
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  const auto truncated = folder.path() / "trunc.h5";
  std::ofstream(truncated, std::ios::binary) << bytes.substr(0, 1000);
  ASSERT_TRUE(Hdf5Reader::is_hdf5(truncated));  // the signature is there, the rest is not
  expect_read_refused([&] { Hdf5Reader{truncated}; }, {"trunc.h5", "cannot open"});
}

}  // namespace
}  // namespace blockfrag
