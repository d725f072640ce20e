#pragma once
// Private to export/: writing HDF5 files with the C API (the model formats
// of docs/hdf5-format.md): datasets contiguous and uncompressed, object
// timestamps off, so the same content always gives the same bytes; every
// failure a bad_input naming the file and the object.
#include <hdf5.h>

#include <string>
#include <vector>

#include <Eigen/Core>

#include "hdf5_handle.h"
#include "igaprep/core/error.h"
#include "igaprep/spline/multipatch.h"

namespace igaprep::exporter::detail {

class Hdf5Writer {
 public:
  explicit Hdf5Writer(std::string path) : path_(std::move(path)) {}

  hid_t check(hid_t id, const std::string& what) const {
    if (id < 0) fail(what);
    return id;
  }
  void check_status(herr_t status, const std::string& what) const {
    if (status < 0) fail(what);
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw bad_input("cannot write '" + path_ + "': HDF5 failed at " + what + " (disk full or no permission?)");
  }

  // The file at `temp` (the atomic write's temporary), its root attributes
  // format and format_version set. Default file properties: no timestamps
  // in object headers and no creation-order tracking, so the bytes depend
  // only on the content.
  H5Handle create_file(const std::string& temp, const std::string& format, int version) const {
    H5Handle fcpl(check(H5Pcreate(H5P_FILE_CREATE), "file properties"));
    H5Handle file(check(H5Fcreate(temp.c_str(), H5F_ACC_TRUNC, fcpl.get(), H5P_DEFAULT), "file creation"));
    string_attribute(file.get(), "format", "attribute /format", format);
    int_attribute(file.get(), "format_version", "attribute /format_version", version);
    return file;
  }

  // Group creation properties without modification times.
  H5Handle group_props() const {
    H5Handle p(check(H5Pcreate(H5P_GROUP_CREATE), "property list"));
    check_status(H5Pset_obj_track_times(p.get(), false), "property list");
    return p;
  }
  H5Handle dataset_props() const {
    H5Handle p(check(H5Pcreate(H5P_DATASET_CREATE), "property list"));
    check_status(H5Pset_obj_track_times(p.get(), false), "property list");
    return p;
  }

  H5Handle create_group(hid_t parent, const std::string& name, const std::string& full) const {
    H5Handle gcpl = group_props();
    return H5Handle(check(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, gcpl.get(), H5P_DEFAULT), full));
  }

  // A dataset of the given shape from a C-ordered buffer (file type, memory type).
  void write_dataset(hid_t parent, const std::string& name, const std::string& full, hid_t file_type,
                     hid_t mem_type, const std::vector<hsize_t>& shape, const void* data) const {
    H5Handle space(check(H5Screate_simple(static_cast<int>(shape.size()), shape.data(), nullptr), full));
    H5Handle dcpl = dataset_props();
    H5Handle ds(check(H5Dcreate2(parent, name.c_str(), file_type, space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT), full));
    hsize_t n = 1;
    for (hsize_t s : shape) n *= s;
    if (n > 0) check_status(H5Dwrite(ds.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), full);
  }

  void write_strings(hid_t parent, const std::string& name, const std::string& full,
                     const std::vector<std::string>& strings) const {
    H5Handle type = string_type();
    std::vector<const char*> ptrs;
    for (const std::string& s : strings) ptrs.push_back(s.c_str());
    write_dataset(parent, name, full, type.get(), type.get(), {static_cast<hsize_t>(strings.size())}, ptrs.data());
  }

  void attribute(hid_t obj, const std::string& name, const std::string& full, hid_t file_type, hid_t mem_type,
                 const std::vector<hsize_t>& shape, const void* data) const {
    H5Handle space(check(shape.empty() ? H5Screate(H5S_SCALAR)
                                       : H5Screate_simple(static_cast<int>(shape.size()), shape.data(), nullptr),
                         full));
    H5Handle a(check(H5Acreate2(obj, name.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT), full));
    check_status(H5Awrite(a.get(), mem_type, data), full);
  }
  void int_attribute(hid_t obj, const std::string& name, const std::string& full, int value) const {
    attribute(obj, name, full, H5T_STD_I32LE, H5T_NATIVE_INT, {}, &value);
  }
  void double_attribute(hid_t obj, const std::string& name, const std::string& full, double value) const {
    attribute(obj, name, full, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {}, &value);
  }
  void string_attribute(hid_t obj, const std::string& name, const std::string& full, const std::string& value) const {
    H5Handle type = string_type();
    const char* p = value.c_str();
    attribute(obj, name, full, type.get(), type.get(), {}, &p);
  }

  // Variable-length UTF-8 strings: h5py reads them as str.
  H5Handle string_type() const {
    H5Handle t(check(H5Tcopy(H5T_C_S1), "string type"));
    check_status(H5Tset_size(t.get(), H5T_VARIABLE), "string type");
    check_status(H5Tset_cset(t.get(), H5T_CSET_UTF8), "string type");
    return t;
  }

 private:
  std::string path_;
};

// Rows of an n x 3 matrix as a C-ordered (n, 3) buffer.
inline std::vector<double> row_major(const Eigen::MatrixXd& m) {
  std::vector<double> out(static_cast<size_t>(m.rows()) * m.cols());
  for (Eigen::Index r = 0; r < m.rows(); ++r)
    for (Eigen::Index c = 0; c < m.cols(); ++c) out[static_cast<size_t>(r) * m.cols() + c] = m(r, c);
  return out;
}

// /materials (name, young_modulus, poisson_ratio) and, when any is set,
// /provenance (generator, case, inputs), as in the multipatch format.
void write_materials(const Hdf5Writer& w, hid_t root, const std::vector<spline::Material>& materials);
void write_provenance(const Hdf5Writer& w, hid_t root, const std::string& generator, const std::string& case_json,
                      const std::string& inputs);

}  // namespace igaprep::exporter::detail
