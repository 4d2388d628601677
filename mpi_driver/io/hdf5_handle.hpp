// What the HDF5 writer and reader share: an owning handle over the C API's identifiers, and
// errors as exceptions instead of HDF5's own printing of its error stack.
#pragma once

#include <hdf5.h>

#include <string>

#include "mpi_driver/io/hdf5_file.hpp"

namespace blockfrag::hdf5 {

// The operating system's reason for the failure HDF5 just reported ("No space left on device"),
// which its file drivers put in their entry of the error stack, as " (reason)"; empty if none.
inline std::string system_reason() {
  std::string reason;
  H5Ewalk2(
      H5E_DEFAULT, H5E_WALK_DOWNWARD,
      [](unsigned, const H5E_error2_t* error, void* found) -> herr_t {
        const std::string text = error->desc ? error->desc : "";
        const std::string marker = "error message = '";
        const auto start = text.find(marker);
        auto& first_reason = *static_cast<std::string*>(found);
        if (start != std::string::npos && first_reason.empty()) {
          const auto from = start + marker.size();
          first_reason = text.substr(from, text.find('\'', from) - from);
        }
        return 0;
      },
      &reason);
  return reason.empty() ? reason : " (" + reason + ")";
}

// Owns one HDF5 identifier and closes it with the matching H5*close.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t), const std::string& what) : id_(id), close_(close) {
    if (id_ < 0) throw Hdf5Error("HDF5: cannot " + what + system_reason());
  }
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  Handle(Handle&& other) noexcept : id_(other.id_), close_(other.close_) { other.id_ = -1; }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  hid_t get() const { return id_; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

inline void check(herr_t status, const std::string& what) {
  if (status < 0) throw Hdf5Error("HDF5: cannot " + what + system_reason());
}

// Errors are reported by exceptions; HDF5's own printing of its error stack would only add noise.
inline void silence_error_printing() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

}  // namespace blockfrag::hdf5
