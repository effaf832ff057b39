#include "common/hdf5.h"

#include <array>
#include <ctime>

#include "common/exit_status.h"

namespace ddb::app::hdf5 {

namespace {

/// The message of the innermost entry of HDF5's error stack (where the failure was
/// detected: "unable to open file: name = ..., errno = 2, ..."), or "" if it is empty.
herr_t keepInnermost(unsigned, const H5E_error2_t* error, void* message) {
  if (error->desc != nullptr) *static_cast<std::string*>(message) = error->desc;
  return 0;
}

std::string hdf5Reason() {
  std::string message;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, keepInnermost, &message);
  H5Eclear2(H5E_DEFAULT);
  return message;
}

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& what) {
  const std::string reason = hdf5Reason();
  throw IoError(file.string() + ": cannot " + what + (reason.empty() ? "" : ": " + reason));
}

}  // namespace

void quiet() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

hid_t check(hid_t id, const std::filesystem::path& file, const std::string& what) {
  if (id < 0) fail(file, what);
  return id;
}

void checkStatus(herr_t status, const std::filesystem::path& file, const std::string& what) {
  if (status < 0) fail(file, what);
}

Handle stringType(const std::filesystem::path& file) {
  Handle type(H5Tcopy(H5T_C_S1), file, "create a string type");
  checkStatus(H5Tset_size(type.get(), H5T_VARIABLE), file, "create a string type");
  checkStatus(H5Tset_cset(type.get(), H5T_CSET_UTF8), file, "create a string type");
  return type;
}

Handle complexType(const std::filesystem::path& file) {
  Handle type(H5Tcreate(H5T_COMPOUND, 2 * sizeof(double)), file, "create a complex type");
  checkStatus(H5Tinsert(type.get(), "r", 0, H5T_NATIVE_DOUBLE), file, "create a complex type");
  checkStatus(H5Tinsert(type.get(), "i", sizeof(double), H5T_NATIVE_DOUBLE), file,
              "create a complex type");
  return type;
}

void writeAttribute(hid_t on, const char* name, hid_t type, const void* value,
                    const std::filesystem::path& file) {
  const std::string what = std::string("write the attribute ") + name;
  const Handle space(H5Screate(H5S_SCALAR), file, what);
  const Handle attribute(H5Acreate2(on, name, type, space.get(), H5P_DEFAULT, H5P_DEFAULT), file,
                         what);
  checkStatus(H5Awrite(attribute.get(), type, value), file, what);
}

void writeAttribute(hid_t on, const char* name, const std::string& value,
                    const std::filesystem::path& file) {
  const Handle type = stringType(file);
  const char* text = value.c_str();
  writeAttribute(on, name, type.get(), &text, file);
}

void readAttribute(hid_t on, const char* name, hid_t type, void* value,
                   const std::filesystem::path& file) {
  const std::string what = std::string("read the attribute ") + name;
  if (H5Aexists(on, name) <= 0) {
    throw IoError(file.string() + ": not a fluid-relax HDF5 file: no attribute " + name);
  }
  const Handle attribute(H5Aopen(on, name, H5P_DEFAULT), file, what);
  checkStatus(H5Aread(attribute.get(), type, value), file, what);
}

std::string readStringAttribute(hid_t on, const char* name, const std::filesystem::path& file) {
  const Handle type = stringType(file);
  char* text = nullptr;
  readAttribute(on, name, type.get(), &text, file);
  std::string value = text != nullptr ? text : "";
  H5free_memory(text);
  return value;
}

Handle createDataset(hid_t on, const char* name, hid_t type, const RowShape& row,
                     const std::filesystem::path& file) {
  constexpr hsize_t kNumberChunk = 1024;
  const std::string what = std::string("create the dataset ") + name;
  std::array<hsize_t, 3> dims{0, row.dims[0], row.dims[1]};
  std::array<hsize_t, 3> max{H5S_UNLIMITED, row.dims[0], row.dims[1]};
  std::array<hsize_t, 3> chunk{row.rank == 0 ? kNumberChunk : 1, row.dims[0], row.dims[1]};
  const Handle space(H5Screate_simple(row.rank + 1, dims.data(), max.data()), file, what);
  const Handle properties(H5Pcreate(H5P_DATASET_CREATE), file, what);
  checkStatus(H5Pset_chunk(properties.get(), row.rank + 1, chunk.data()), file, what);
  return Handle(H5Dcreate2(on, name, type, space.get(), H5P_DEFAULT, properties.get(), H5P_DEFAULT),
                file, what);
}

void resize(hid_t dataset, const RowShape& row, hsize_t rows, const std::filesystem::path& file) {
  std::array<hsize_t, 3> dims{rows, row.dims[0], row.dims[1]};
  checkStatus(H5Dset_extent(dataset, dims.data()), file, "resize a dataset");
}

void appendRow(hid_t dataset, hid_t type, const RowShape& row, hsize_t at, const void* data,
               const std::filesystem::path& file) {
  resize(dataset, row, at + 1, file);
  const Handle file_space(H5Dget_space(dataset), file, "append a frame");
  std::array<hsize_t, 3> start{at, 0, 0};
  std::array<hsize_t, 3> count{1, row.dims[0], row.dims[1]};
  checkStatus(H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start.data(), nullptr,
                                  count.data(), nullptr),
              file, "append a frame");
  const Handle memory_space(H5Screate_simple(row.rank + 1, count.data(), nullptr), file,
                            "append a frame");
  checkStatus(H5Dwrite(dataset, type, memory_space.get(), file_space.get(), H5P_DEFAULT, data),
              file, "append a frame");
}

std::string utcNow() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

}  // namespace ddb::app::hdf5
