// The HDF5 C API (Debian's libhdf5, 1.10) for the apps' HDF5 files
// (docs/reference/command-lines-and-files.md, "fluid.hdf5"): an owning handle per identifier, and
// failures as IoError naming the file with HDF5's own reason. HDF5's automatic printing of its
// error stack to stderr is off (quiet()), so that a failure is reported once, through the app's
// message.
#pragma once

#include <hdf5.h>

#include <array>
#include <filesystem>
#include <string>

namespace ddb::app::hdf5 {

/// Turns off HDF5's printing of its error stack to stderr (H5Eset_auto) for this process.
void quiet();

/// Returns `id` if it is valid (>= 0), else throws IoError "<file>: cannot <what>: <HDF5's
/// innermost message>".
hid_t check(hid_t id, const std::filesystem::path& file, const std::string& what);

/// As check(), for a status (herr_t < 0 is a failure).
void checkStatus(herr_t status, const std::filesystem::path& file, const std::string& what);

/// Owns one HDF5 identifier (file, dataset, dataspace, type, property list, attribute)
/// and closes it with H5Idec_ref, which closes an identifier of any kind.
class Handle {
 public:
  Handle() = default;
  /// Takes `id` as check(id, file, what) returns it.
  Handle(hid_t id, const std::filesystem::path& file, const std::string& what)
      : id_(check(id, file, what)) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle(Handle&& other) noexcept : id_(other.id_) { other.id_ = H5I_INVALID_HID; }
  Handle& operator=(Handle&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = other.id_;
      other.id_ = H5I_INVALID_HID;
    }
    return *this;
  }
  ~Handle() { reset(); }

  hid_t get() const { return id_; }
  explicit operator bool() const { return id_ >= 0; }

 private:
  void reset() noexcept {
    if (id_ >= 0) H5Idec_ref(id_);
    id_ = H5I_INVALID_HID;
  }

  hid_t id_ = H5I_INVALID_HID;
};

/// A variable-length UTF-8 string type: h5py reads it as str (a fixed-length string would
/// come back as bytes, and quflow compares the attribute `qtype` with the str "shr").
Handle stringType(const std::filesystem::path& file);

/// h5py's complex128: the compound {r, i} of two float64 (the layout of std::complex<double>).
Handle complexType(const std::filesystem::path& file);

/// Writes the scalar attribute `name` = `value` of `type` on the object `on` (H5T_NATIVE_*).
void writeAttribute(hid_t on, const char* name, hid_t type, const void* value,
                    const std::filesystem::path& file);

/// Writes the scalar string attribute `name` = `value` on `on`.
void writeAttribute(hid_t on, const char* name, const std::string& value,
                    const std::filesystem::path& file);

/// Reads the scalar attribute `name` of the object `on` as `type` (H5T_NATIVE_*) into
/// `value`; throws IoError naming `file` if it is missing or of another kind.
void readAttribute(hid_t on, const char* name, hid_t type, void* value,
                   const std::filesystem::path& file);

/// Reads the scalar string attribute `name` of `on` (as writeAttribute writes it).
std::string readStringAttribute(hid_t on, const char* name, const std::filesystem::path& file);

/// The shape of one frame's row of an extendable per-frame dataset: rank 0 (a number), 1 (a
/// vector of dims[0]) or 2 (a dims[0] × dims[1] matrix). A frame is one row of each dataset.
struct RowShape {
  int rank = 0;
  std::array<hsize_t, 2> dims{};
};

/// Creates in `on` (a file or group) the extendable dataset `name` of `type` with no rows,
/// chunked by rows (a number's dataset by 1024 rows: a chunk per frame would cost a chunk index
/// entry per number).
Handle createDataset(hid_t on, const char* name, hid_t type, const RowShape& row,
                     const std::filesystem::path& file);

/// Sets the row count of `dataset` to `rows`.
void resize(hid_t dataset, const RowShape& row, hsize_t rows, const std::filesystem::path& file);

/// Writes `data` (of `type` in memory) as row `at` of `dataset`, which has `at` rows.
void appendRow(hid_t dataset, hid_t type, const RowShape& row, hsize_t at, const void* data,
               const std::filesystem::path& file);

/// The current time as ISO 8601 UTC ("2026-11-24T15:40:00Z"), for the files' `created`.
std::string utcNow();

}  // namespace ddb::app::hdf5
