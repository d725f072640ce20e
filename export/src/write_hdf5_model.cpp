// Writer of the HDF5 model format, version 1 (ARCHITECTURE.md). Datasets are
// contiguous and uncompressed, and object timestamps are off, so the same
// model always gives the same bytes.
#include <cstdio>
#include <vector>

#include "hdf5_writer.h"
#include "igaprep/core/atomic_file.h"
#include "igaprep/core/error.h"
#include "igaprep/export/hdf5_model.h"
#include "model_checks.h"

namespace igaprep::exporter {

namespace {
using detail::H5Handle;
using detail::row_major;

void write_file(const spline::MultiPatch& model, const std::string& path, const std::string& temp) {
  detail::Hdf5Writer w(path);
  H5Handle file = w.create_file(temp, "igaprep-multipatch", 1);
  const hid_t root = file.get();
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

  detail::write_materials(w, root, model.materials);
  detail::write_provenance(w, root, model.provenance_generator, model.provenance_case, model.provenance_inputs);
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
