// Writer of the HDF5 model format, version 1 (ARCHITECTURE.md). Datasets are
// contiguous and uncompressed, and object timestamps are off, so the same
// model always gives the same bytes.
#include <cstdio>
#include <vector>

#include "hdf5_handle.h"
#include "igaprep/core/atomic_file.h"
#include "igaprep/core/error.h"
#include "igaprep/export/hdf5_model.h"
#include "model_checks.h"

namespace igaprep::exporter {

namespace {
using detail::H5Handle;

class Writer {
 public:
  explicit Writer(std::string path) : path_(std::move(path)) {}

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
std::vector<double> row_major(const Eigen::MatrixXd& m) {
  std::vector<double> out(static_cast<size_t>(m.rows()) * m.cols());
  for (Eigen::Index r = 0; r < m.rows(); ++r)
    for (Eigen::Index c = 0; c < m.cols(); ++c) out[static_cast<size_t>(r) * m.cols() + c] = m(r, c);
  return out;
}

void write_file(const spline::MultiPatch& model, const std::string& path, const std::string& temp) {
  Writer w(path);
  // Earliest library format (no timestamps in object headers); tracking of
  // creation order off so the bytes depend only on the model.
  H5Handle fcpl(w.check(H5Pcreate(H5P_FILE_CREATE), "file properties"));
  H5Handle file(w.check(H5Fcreate(temp.c_str(), H5F_ACC_TRUNC, fcpl.get(), H5P_DEFAULT), "file creation"));
  const hid_t root = file.get();

  w.string_attribute(root, "format", "attribute /format", "igaprep-multipatch");
  w.int_attribute(root, "format_version", "attribute /format_version", 1);
  if (model.has_solution) {
    w.double_attribute(root, "strain_energy", "attribute /strain_energy", model.strain_energy);
    w.double_attribute(root, "max_displacement", "attribute /max_displacement", model.max_displacement);
  }

  H5Handle patches = w.create_group(root, "patches", "group /patches");
  w.int_attribute(patches.get(), "count", "attribute /patches/count", static_cast<int>(model.patches.size()));
  for (size_t i = 0; i < model.patches.size(); ++i) {
    const spline::Patch& p = model.patches[i];
    char name[32];
    std::snprintf(name, sizeof(name), "%06zu", i);
    const std::string g = std::string("/patches/") + name;
    H5Handle pg = w.create_group(patches.get(), name, "group " + g);
    const int degrees[3] = {p.degrees[0], p.degrees[1], p.degrees[2]};
    w.attribute(pg.get(), "degrees", "attribute " + g + "/degrees", H5T_STD_I32LE, H5T_NATIVE_INT, {3}, degrees);
    w.int_attribute(pg.get(), "material", "attribute " + g + "/material", p.material);
    for (int d = 0; d < 3; ++d) {
      const std::string kn = std::string("knots_") + detail::direction_name(d);
      w.write_dataset(pg.get(), kn, "dataset " + g + "/" + kn, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                      {static_cast<hsize_t>(p.knots[d].size())}, p.knots[d].data());
    }
    const std::vector<hsize_t> grid = {static_cast<hsize_t>(p.count(2)), static_cast<hsize_t>(p.count(1)),
                                       static_cast<hsize_t>(p.count(0))};
    std::vector<hsize_t> grid3 = grid;
    grid3.push_back(3);
    const std::vector<double> cp = row_major(p.control_points);
    w.write_dataset(pg.get(), "control_points", "dataset " + g + "/control_points", H5T_IEEE_F64LE,
                    H5T_NATIVE_DOUBLE, grid3, cp.data());
    if (p.rational())
      w.write_dataset(pg.get(), "weights", "dataset " + g + "/weights", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, grid,
                      p.weights.data());
    if (p.displacement.size() > 0) {
      const std::vector<double> u = row_major(p.displacement);
      w.write_dataset(pg.get(), "displacement", "dataset " + g + "/displacement", H5T_IEEE_F64LE,
                      H5T_NATIVE_DOUBLE, grid3, u.data());
    }
  }

  const size_t ni = model.interfaces.size();
  std::vector<int> faces(ni * 10);
  std::vector<int> surfaces(ni);
  for (size_t k = 0; k < ni; ++k) {
    const spline::Interface& f = model.interfaces[k];
    const int row[10] = {f.patch_a,   f.side_a.index(), f.patch_b,   f.side_b.index(), f.dirmap[0],
                         f.dirmap[1], f.dirmap[2],      f.orient[0], f.orient[1],      f.orient[2]};
    std::copy(row, row + 10, faces.begin() + 10 * k);
    surfaces[k] = f.surface;
  }
  w.write_dataset(root, "interfaces", "dataset /interfaces", H5T_STD_I32LE, H5T_NATIVE_INT,
                  {static_cast<hsize_t>(ni), 10}, faces.data());
  w.write_dataset(root, "interface_surfaces", "dataset /interface_surfaces", H5T_STD_I32LE, H5T_NATIVE_INT,
                  {static_cast<hsize_t>(ni)}, surfaces.data());

  const size_t nb = model.boundaries.size();
  std::vector<int> bounds(nb * 3);
  for (size_t k = 0; k < nb; ++k) {
    bounds[3 * k] = model.boundaries[k].patch;
    bounds[3 * k + 1] = model.boundaries[k].side.index();
    bounds[3 * k + 2] = model.boundaries[k].label;
  }
  w.write_dataset(root, "boundaries", "dataset /boundaries", H5T_STD_I32LE, H5T_NATIVE_INT,
                  {static_cast<hsize_t>(nb), 3}, bounds.data());
  w.write_strings(root, "labels", "dataset /labels", model.labels);

  H5Handle mats = w.create_group(root, "materials", "group /materials");
  std::vector<std::string> names;
  std::vector<double> young, poisson;
  for (const spline::Material& m : model.materials) {
    names.push_back(m.name);
    young.push_back(m.young_modulus);
    poisson.push_back(m.poisson_ratio);
  }
  const std::vector<hsize_t> nm = {static_cast<hsize_t>(model.materials.size())};
  w.write_strings(mats.get(), "name", "dataset /materials/name", names);
  w.write_dataset(mats.get(), "young_modulus", "dataset /materials/young_modulus", H5T_IEEE_F64LE,
                  H5T_NATIVE_DOUBLE, nm, young.data());
  w.write_dataset(mats.get(), "poisson_ratio", "dataset /materials/poisson_ratio", H5T_IEEE_F64LE,
                  H5T_NATIVE_DOUBLE, nm, poisson.data());

  if (!model.provenance_generator.empty() || !model.provenance_case.empty() || !model.provenance_inputs.empty()) {
    H5Handle prov = w.create_group(root, "provenance", "group /provenance");
    w.string_attribute(prov.get(), "generator", "attribute /provenance/generator", model.provenance_generator);
    w.string_attribute(prov.get(), "case", "attribute /provenance/case", model.provenance_case);
    w.string_attribute(prov.get(), "inputs", "attribute /provenance/inputs", model.provenance_inputs);
  }
  w.check_status(H5Fflush(root, H5F_SCOPE_GLOBAL), "flush");
}
}  // namespace

void write_hdf5_model(const spline::MultiPatch& model, AtomicPath& target) {
  detail::check_model_for_writing(model, "'" + target.path() + "'");
  detail::SilenceHdf5Errors quiet;
  write_file(model, target.path(), target.temp_path());  // all handles closed on return
}

void write_hdf5_model(const spline::MultiPatch& model, const std::string& path) {
  AtomicPath target(path);
  write_hdf5_model(model, target);
  target.commit();
}

}  // namespace igaprep::exporter
