// Reading fluid.hdf5's datasets back through the HDF5 C API, for the tests of its writer
// (test_fluid_h5) and of the apps that write it (test_fluid_relax_mpi).
#pragma once

#include <hdf5.h>

#include <complex>
#include <filesystem>
#include <vector>

namespace ddb::test {

/// The whole dataset `name` of `file` read as `type` (H5T_NATIVE_*, or complexType() for
/// `mat`), and its row count.
template <typename T>
std::vector<T> readAll(const std::filesystem::path& file, const char* name, hid_t type,
                       hsize_t* rows) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t d = H5Dopen2(f, name, H5P_DEFAULT);
  const hid_t space = H5Dget_space(d);
  std::vector<hsize_t> dims(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)));
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  hsize_t count = 1;
  for (const hsize_t dim : dims) count *= dim;
  std::vector<T> values(count);
  if (count > 0) H5Dread(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
  *rows = dims[0];
  H5Sclose(space);
  H5Dclose(d);
  H5Fclose(f);
  return values;
}

/// h5py's complex as {r, i}, the type of `mat`; the caller H5Tclose()s it.
inline hid_t complexType() {
  const hid_t complex = H5Tcreate(H5T_COMPOUND, 2 * sizeof(double));
  H5Tinsert(complex, "r", 0, H5T_NATIVE_DOUBLE);
  H5Tinsert(complex, "i", sizeof(double), H5T_NATIVE_DOUBLE);
  return complex;
}

}  // namespace ddb::test
