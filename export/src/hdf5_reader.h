#pragma once
// Private to export/: reading HDF5 model files with the C API. Every object
// is checked for presence, shape, type and values before it is used; a
// defect gives bad_input naming the file and the object.
#include <hdf5.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "hdf5_handle.h"
#include "igaprep/core/error.h"
#include "igaprep/core/input_files.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::exporter::detail {

class Hdf5Reader {
 public:
  explicit Hdf5Reader(std::string path) : path_(std::move(path)) {}

  [[noreturn]] void bad(const std::string& where, const std::string& message) const {
    throw bad_input("'" + path_ + "': " + where + ": " + message);
  }

  void open() {
    {
      std::ifstream probe(path_, std::ios::binary);
      if (!probe) throw bad_input("cannot open '" + path_ + "' (missing or not readable)");
    }
    if (H5Fis_hdf5(path_.c_str()) <= 0)
      throw bad_input("'" + path_ + "' is not an HDF5 file (or it is truncated or damaged)");
    file_ = H5Handle(H5Fopen(path_.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
    if (!file_.valid())
      throw bad_input("'" + path_ + "' cannot be opened as HDF5 (truncated or damaged file?)");
  }
  hid_t root() const { return file_.get(); }
  const std::string& path() const { return path_; }

  bool has_link(hid_t loc, const std::string& name) const {
    return H5Lexists(loc, name.c_str(), H5P_DEFAULT) > 0;
  }
  bool has_attribute(hid_t obj, const std::string& name) const { return H5Aexists(obj, name.c_str()) > 0; }

  H5Handle open_group(hid_t loc, const std::string& name, const std::string& full) const {
    if (!has_link(loc, name)) bad("group " + full, "missing");
    H5Handle g(H5Gopen2(loc, name.c_str(), H5P_DEFAULT));
    if (!g.valid()) bad("group " + full, "cannot be opened as a group (damaged file?)");
    return g;
  }
  H5Handle open_dataset(hid_t loc, const std::string& name, const std::string& full) const {
    if (!has_link(loc, name)) bad("dataset " + full, "missing");
    H5Handle d(H5Dopen2(loc, name.c_str(), H5P_DEFAULT));
    if (!d.valid()) bad("dataset " + full, "cannot be opened as a dataset (damaged file?)");
    return d;
  }

  // A dataset's declared shape is only a promise: one that holds far more
  // values than the file has bytes (the format stores them uncompressed) is
  // refused before anything is allocated.
  void check_declared_size(const std::vector<hsize_t>& dims, std::size_t value_bytes, const std::string& where) const {
    std::error_code ec;
    const double file_bytes = static_cast<double>(std::filesystem::file_size(path_, ec));
    double values = 1.0;
    for (hsize_t d : dims) values *= static_cast<double>(d);
    if (values * static_cast<double>(value_bytes) > 16.0 * file_bytes + 65536.0)
      bad(where, "shape " + shape_text(dims) + " declares " + std::to_string(static_cast<long long>(values)) +
                     " values, more than the file's " + std::to_string(static_cast<long long>(file_bytes)) +
                     " bytes can hold (damaged or hostile file)");
  }

  std::vector<hsize_t> shape_of(hid_t space, const std::string& where) const {
    const int rank = H5Sget_simple_extent_ndims(space);
    if (rank < 0) bad(where, "unreadable dataspace");
    std::vector<hsize_t> dims(rank);
    if (rank > 0 && H5Sget_simple_extent_dims(space, dims.data(), nullptr) < 0) bad(where, "unreadable dataspace");
    return dims;
  }
  static std::string shape_text(const std::vector<hsize_t>& dims) {
    std::string s = "(";
    for (size_t i = 0; i < dims.size(); ++i) s += (i ? ", " : "") + std::to_string(dims[i]);
    return s + (dims.size() == 1 ? ",)" : ")");
  }
  void expect_rank(const std::vector<hsize_t>& dims, size_t rank, const std::string& where,
                   const std::string& expected) const {
    if (dims.size() != rank) bad(where, "shape " + shape_text(dims) + ", expected " + expected);
  }

  // float64 dataset: returns the values (C order) and its shape.
  std::vector<double> read_doubles(hid_t loc, const std::string& name, const std::string& full,
                                   std::vector<hsize_t>* dims) const {
    const std::string where = "dataset " + full;
    H5Handle ds = open_dataset(loc, name, full);
    H5Handle type(H5Dget_type(ds.get()));
    if (!type.valid() || H5Tget_class(type.get()) != H5T_FLOAT || H5Tget_size(type.get()) != 8)
      bad(where, "type is not float64");
    H5Handle space(H5Dget_space(ds.get()));
    *dims = shape_of(space.get(), where);
    check_declared_size(*dims, sizeof(double), where);
    hsize_t n = 1;
    for (hsize_t d : *dims) n *= d;
    std::vector<double> v(n);
    if (n > 0 && H5Dread(ds.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) < 0)
      bad(where, "cannot be read (truncated or damaged file?)");
    for (hsize_t i = 0; i < n; ++i)
      if (!std::isfinite(v[i])) bad(where, "non-finite value at flat index " + std::to_string(i));
    return v;
  }

  // Integer dataset (any integer width; the format writes int32).
  std::vector<long long> read_ints(hid_t loc, const std::string& name, const std::string& full,
                                   std::vector<hsize_t>* dims) const {
    const std::string where = "dataset " + full;
    H5Handle ds = open_dataset(loc, name, full);
    H5Handle type(H5Dget_type(ds.get()));
    if (!type.valid() || H5Tget_class(type.get()) != H5T_INTEGER) bad(where, "type is not an integer (int32)");
    H5Handle space(H5Dget_space(ds.get()));
    *dims = shape_of(space.get(), where);
    check_declared_size(*dims, sizeof(int), where);
    hsize_t n = 1;
    for (hsize_t d : *dims) n *= d;
    std::vector<long long> v(n);
    if (n > 0 && H5Dread(ds.get(), H5T_NATIVE_LLONG, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) < 0)
      bad(where, "cannot be read (truncated or damaged file?)");
    return v;
  }

  // Strings (variable-length or fixed-length) of a rank-1 dataset.
  std::vector<std::string> read_strings(hid_t loc, const std::string& name, const std::string& full) const {
    const std::string where = "dataset " + full;
    H5Handle ds = open_dataset(loc, name, full);
    H5Handle type(H5Dget_type(ds.get()));
    if (!type.valid() || H5Tget_class(type.get()) != H5T_STRING) bad(where, "type is not a string");
    H5Handle space(H5Dget_space(ds.get()));
    const std::vector<hsize_t> dims = shape_of(space.get(), where);
    expect_rank(dims, 1, where, "(N,)");
    check_declared_size(dims, 1, where);
    return read_string_values(type.get(), space.get(), dims[0], where, [&](hid_t mem, void* buf) {
      return H5Dread(ds.get(), mem, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf);
    });
  }

  template <class ReadFn>
  std::vector<std::string> read_string_values(hid_t file_type, hid_t space, hsize_t n, const std::string& where,
                                              ReadFn read) const {
    std::vector<std::string> out;
    if (n == 0) return out;
    if (H5Tis_variable_str(file_type) > 0) {
      H5Handle mem(H5Tcopy(H5T_C_S1));
      H5Tset_size(mem.get(), H5T_VARIABLE);
      H5Tset_cset(mem.get(), H5Tget_cset(file_type));
      std::vector<char*> ptrs(n, nullptr);
      if (read(mem.get(), ptrs.data()) < 0) bad(where, "cannot be read (truncated or damaged file?)");
      for (char* p : ptrs) out.emplace_back(p ? p : "");
      H5Dvlen_reclaim(mem.get(), space, H5P_DEFAULT, ptrs.data());
    } else {
      const size_t size = H5Tget_size(file_type);
      H5Handle mem(H5Tcopy(file_type));
      std::vector<char> buf(size * n + 1, '\0');
      if (read(mem.get(), buf.data()) < 0) bad(where, "cannot be read (truncated or damaged file?)");
      for (hsize_t i = 0; i < n; ++i) {
        const char* s = buf.data() + i * size;
        out.emplace_back(s, strnlen(s, size));
      }
    }
    return out;
  }

  // Attributes.
  H5Handle open_attribute(hid_t obj, const std::string& name, const std::string& full) const {
    if (!has_attribute(obj, name)) bad("attribute " + full, "missing");
    H5Handle a(H5Aopen(obj, name.c_str(), H5P_DEFAULT));
    if (!a.valid()) bad("attribute " + full, "cannot be opened (damaged file?)");
    return a;
  }
  hsize_t attribute_size(hid_t a, const std::string& where, std::vector<hsize_t>* dims) const {
    H5Handle space(H5Aget_space(a));
    *dims = shape_of(space.get(), where);
    hsize_t n = 1;
    for (hsize_t d : *dims) n *= d;
    return n;
  }
  std::vector<long long> int_attribute(hid_t obj, const std::string& name, const std::string& full,
                                       hsize_t count) const {
    const std::string where = "attribute " + full;
    H5Handle a = open_attribute(obj, name, full);
    H5Handle type(H5Aget_type(a.get()));
    if (!type.valid() || H5Tget_class(type.get()) != H5T_INTEGER) bad(where, "type is not an integer");
    std::vector<hsize_t> dims;
    const hsize_t n = attribute_size(a.get(), where, &dims);
    if (n != count || dims.size() > 1)
      bad(where, "shape " + shape_text(dims) + ", expected " + (count == 1 ? "a scalar" : "(" + std::to_string(count) + ",)"));
    std::vector<long long> v(n);
    if (H5Aread(a.get(), H5T_NATIVE_LLONG, v.data()) < 0) bad(where, "cannot be read");
    return v;
  }
  int int_scalar(hid_t obj, const std::string& name, const std::string& full) const {
    const long long v = int_attribute(obj, name, full, 1)[0];
    if (v < -2147483647LL || v > 2147483647LL) bad("attribute " + full, "value out of int range");
    return static_cast<int>(v);
  }
  double double_scalar(hid_t obj, const std::string& name, const std::string& full) const {
    const std::string where = "attribute " + full;
    H5Handle a = open_attribute(obj, name, full);
    H5Handle type(H5Aget_type(a.get()));
    if (!type.valid() || H5Tget_class(type.get()) != H5T_FLOAT || H5Tget_size(type.get()) != 8)
      bad(where, "type is not float64");
    std::vector<hsize_t> dims;
    if (attribute_size(a.get(), where, &dims) != 1 || dims.size() > 1) bad(where, "not a scalar");
    double v = 0.0;
    if (H5Aread(a.get(), H5T_NATIVE_DOUBLE, &v) < 0) bad(where, "cannot be read");
    if (!std::isfinite(v)) bad(where, "non-finite value");
    return v;
  }
  std::string string_scalar(hid_t obj, const std::string& name, const std::string& full) const {
    const std::string where = "attribute " + full;
    H5Handle a = open_attribute(obj, name, full);
    H5Handle type(H5Aget_type(a.get()));
    if (!type.valid() || H5Tget_class(type.get()) != H5T_STRING) bad(where, "type is not a string");
    std::vector<hsize_t> dims;
    if (attribute_size(a.get(), where, &dims) != 1 || dims.size() > 1) bad(where, "not a single string");
    H5Handle space(H5Aget_space(a.get()));
    return read_string_values(type.get(), space.get(), 1, where,
                              [&](hid_t mem, void* buf) { return H5Aread(a.get(), mem, buf); })[0];
  }

 private:
  std::string path_;
  H5Handle file_;
};

// Opens the model file at `path` (a regular file, HDF5's own error printing
// off) and returns read(reader).
template <class Read>
auto read_model_file(const std::string& path, Read read) {
  require_regular_file(path, "model file");
  SilenceHdf5Errors quiet;
  Hdf5Reader r(path);
  r.open();
  return read(r);
}

// The root attributes format (== `format`) and format_version (== 1).
void expect_format(const Hdf5Reader& r, const std::string& format);
// /materials (name, young_modulus, poisson_ratio), as both formats write it.
std::vector<spline::Material> read_materials(const Hdf5Reader& r);
// /provenance's attributes when the group is there (else left empty).
void read_provenance(const Hdf5Reader& r, std::string* generator, std::string* case_json, std::string* inputs);

}  // namespace igaprep::exporter::detail
