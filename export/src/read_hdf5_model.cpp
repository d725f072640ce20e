// Reader of the HDF5 model format, version 1 (ARCHITECTURE.md). Every object
// is checked for presence, shape, type and values before it enters the
// model; a defect gives bad_input naming the file and the dataset.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include "hdf5_reader.h"
#include "igaprep/core/error.h"
#include "igaprep/export/hdf5_model.h"
#include "igaprep/spline/knot_vector.h"
#include "model_checks.h"

namespace igaprep::exporter {

namespace {
using detail::H5Handle;
using Reader = detail::Hdf5Reader;

std::string patch_group_name(int i) {
  char name[32];
  std::snprintf(name, sizeof(name), "%06d", i);
  return name;
}

spline::MultiPatch read_model(Reader& r) {
  const hid_t root = r.root();
  spline::MultiPatch model;
  detail::expect_format(r, "igaprep-multipatch");

  // Labels and materials first: patches, interfaces and boundaries index them.
  model.labels = r.read_strings(root, "labels", "/labels");
  const int nl = static_cast<int>(model.labels.size());
  model.materials = detail::read_materials(r);
  const int nm = static_cast<int>(model.materials.size());

  const bool has_energy = r.has_attribute(root, "strain_energy");
  const bool has_max = r.has_attribute(root, "max_displacement");
  if (has_energy != has_max)
    r.bad(has_energy ? "attribute /max_displacement" : "attribute /strain_energy",
          "missing (a solve result has both strain_energy and max_displacement)");
  if (has_energy) {
    model.has_solution = true;
    model.strain_energy = r.double_scalar(root, "strain_energy", "/strain_energy");
    model.max_displacement = r.double_scalar(root, "max_displacement", "/max_displacement");
  }

  H5Handle patches = r.open_group(root, "patches", "/patches");
  const int count = r.int_scalar(patches.get(), "count", "/patches/count");
  if (count < 0) r.bad("attribute /patches/count", "negative");
  H5G_info_t info;
  if (H5Gget_info(patches.get(), &info) < 0) r.bad("group /patches", "unreadable");
  if (info.nlinks != static_cast<hsize_t>(count))
    r.bad("group /patches", "holds " + std::to_string(info.nlinks) + " members but its attribute count is " + std::to_string(count));
  model.patches.resize(count);
  for (int i = 0; i < count; ++i) {
    spline::Patch& p = model.patches[i];
    const std::string name = patch_group_name(i);
    const std::string g = "/patches/" + name;
    H5Handle pg = r.open_group(patches.get(), name, g);
    const std::vector<long long> deg = r.int_attribute(pg.get(), "degrees", g + "/degrees", 3);
    for (int d = 0; d < 3; ++d) {
      if (deg[d] < 0 || deg[d] > 64) r.bad("attribute " + g + "/degrees", "degree " + std::to_string(deg[d]) + " out of range");
      p.degrees[d] = static_cast<int>(deg[d]);
    }
    p.material = r.int_scalar(pg.get(), "material", g + "/material");
    if (p.material < 0 || p.material >= nm)
      r.bad("attribute " + g + "/material", "material " + std::to_string(p.material) + " but /materials has " + std::to_string(nm) + " entries");

    std::vector<hsize_t> cdims;
    const std::vector<double> cp = r.read_doubles(pg.get(), "control_points", g + "/control_points", &cdims);
    if (cdims.size() != 4 || cdims[3] != 3)
      r.bad("dataset " + g + "/control_points", "shape " + Reader::shape_text(cdims) + ", expected (n_w, n_v, n_u, 3)");
    const long long n[3] = {static_cast<long long>(cdims[2]), static_cast<long long>(cdims[1]), static_cast<long long>(cdims[0])};
    for (int d = 0; d < 3; ++d) {
      const std::string kn = std::string("knots_") + detail::direction_name(d);
      const std::string where = "dataset " + g + "/" + kn;
      std::vector<hsize_t> kd;
      p.knots[d] = r.read_doubles(pg.get(), kn, g + "/" + kn, &kd);
      r.expect_rank(kd, 1, where, "(n + p + 1,)");
      if (static_cast<long long>(p.knots[d].size()) != n[d] + p.degrees[d] + 1)
        r.bad(where, "has " + std::to_string(p.knots[d].size()) + " knots but control_points has n_" +
                         detail::direction_name(d) + " = " + std::to_string(n[d]) + " and degree " +
                         std::to_string(p.degrees[d]) + " needs " + std::to_string(n[d] + p.degrees[d] + 1));
      if (n[d] < p.degrees[d] + 1)
        r.bad("dataset " + g + "/control_points", "n_" + std::string(detail::direction_name(d)) + " = " +
                  std::to_string(n[d]) + " is too few for degree " + std::to_string(p.degrees[d]));
      spline::validate_knot_vector(p.knots[d], p.degrees[d], static_cast<int>(n[d]), "'" + r.path() + "': " + where);
    }
    const long long total = n[0] * n[1] * n[2];
    p.control_points.resize(total, 3);
    for (long long k = 0; k < total; ++k)
      for (int c = 0; c < 3; ++c) p.control_points(k, c) = cp[3 * k + c];

    if (r.has_link(pg.get(), "weights")) {
      const std::string where = "dataset " + g + "/weights";
      std::vector<hsize_t> wd;
      const std::vector<double> w = r.read_doubles(pg.get(), "weights", g + "/weights", &wd);
      if (wd.size() != 3 || wd[0] != cdims[0] || wd[1] != cdims[1] || wd[2] != cdims[2])
        r.bad(where, "shape " + Reader::shape_text(wd) + ", expected " +
                         Reader::shape_text({cdims[0], cdims[1], cdims[2]}) + " like control_points");
      p.weights.resize(total);
      for (long long k = 0; k < total; ++k) {
        if (!(w[k] > 0.0)) r.bad(where, "weight " + std::to_string(k) + " is not positive");
        p.weights[k] = w[k];
      }
    }
    if (r.has_link(pg.get(), "displacement")) {
      const std::string where = "dataset " + g + "/displacement";
      std::vector<hsize_t> ud;
      const std::vector<double> u = r.read_doubles(pg.get(), "displacement", g + "/displacement", &ud);
      if (ud != cdims) r.bad(where, "shape " + Reader::shape_text(ud) + ", expected " + Reader::shape_text(cdims) + " like control_points");
      p.displacement.resize(total, 3);
      for (long long k = 0; k < total; ++k)
        for (int c = 0; c < 3; ++c) p.displacement(k, c) = u[3 * k + c];
    }
  }

  {
    std::vector<hsize_t> fd, sd;
    const std::vector<long long> f = r.read_ints(root, "interfaces", "/interfaces", &fd);
    if (fd.size() != 2 || fd[1] != 10) r.bad("dataset /interfaces", "shape " + Reader::shape_text(fd) + ", expected (N, 10)");
    const std::vector<long long> s = r.read_ints(root, "interface_surfaces", "/interface_surfaces", &sd);
    if (sd.size() != 1 || sd[0] != fd[0])
      r.bad("dataset /interface_surfaces", "shape " + Reader::shape_text(sd) + ", expected (" + std::to_string(fd[0]) + ",) like /interfaces");
    for (hsize_t k = 0; k < fd[0]; ++k) {
      const long long* row = f.data() + 10 * k;
      const std::string where = "dataset /interfaces";
      const std::string rowname = "row " + std::to_string(k);
      for (int a : {0, 2})
        if (row[a] < 0 || row[a] >= count)
          r.bad(where, rowname + " names patch " + std::to_string(row[a]) + " but the file has " + std::to_string(count) + " patches");
      for (int a : {1, 3})
        if (row[a] < 1 || row[a] > 6) r.bad(where, rowname + ": side " + std::to_string(row[a]) + " outside 1..6");
      bool seen[3] = {false, false, false};
      for (int d = 0; d < 3; ++d) {
        if (row[4 + d] < 0 || row[4 + d] > 2 || seen[row[4 + d]])
          r.bad(where, rowname + ": direction map is not a permutation of 0 1 2");
        seen[row[4 + d]] = true;
        if (row[7 + d] != 0 && row[7 + d] != 1) r.bad(where, rowname + ": orientation flags must be 0 or 1");
      }
      if (s[k] < -1 || s[k] >= nl)
        r.bad("dataset /interface_surfaces", "entry " + std::to_string(k) + " = " + std::to_string(s[k]) + " is neither -1 nor a label index (the file has " + std::to_string(nl) + " labels)");
      spline::Interface itf;
      itf.patch_a = static_cast<int>(row[0]);
      itf.side_a = static_cast<int>(row[1]);
      itf.patch_b = static_cast<int>(row[2]);
      itf.side_b = static_cast<int>(row[3]);
      for (int d = 0; d < 3; ++d) {
        itf.dirmap[d] = static_cast<int>(row[4 + d]);
        itf.orient[d] = static_cast<int>(row[7 + d]);
      }
      itf.surface = static_cast<int>(s[k]);
      model.interfaces.push_back(itf);
    }
  }
  {
    std::vector<hsize_t> bd;
    const std::vector<long long> b = r.read_ints(root, "boundaries", "/boundaries", &bd);
    if (bd.size() != 2 || bd[1] != 3) r.bad("dataset /boundaries", "shape " + Reader::shape_text(bd) + ", expected (N, 3)");
    for (hsize_t k = 0; k < bd[0]; ++k) {
      const long long* row = b.data() + 3 * k;
      const std::string rowname = "row " + std::to_string(k);
      if (row[0] < 0 || row[0] >= count)
        r.bad("dataset /boundaries", rowname + " names patch " + std::to_string(row[0]) + " but the file has " + std::to_string(count) + " patches");
      if (row[1] < 1 || row[1] > 6) r.bad("dataset /boundaries", rowname + ": side " + std::to_string(row[1]) + " outside 1..6");
      if (row[2] < 0 || row[2] >= nl)
        r.bad("dataset /boundaries", rowname + ": label " + std::to_string(row[2]) + " but /labels has " + std::to_string(nl) + " entries");
      model.boundaries.push_back({static_cast<int>(row[0]), static_cast<int>(row[1]), static_cast<int>(row[2])});
    }
  }

  detail::read_provenance(r, &model.provenance_generator, &model.provenance_case, &model.provenance_inputs);
  return model;
}
}  // namespace

spline::MultiPatch read_hdf5_model(const std::string& path) { return detail::read_model_file(path, read_model); }

}  // namespace igaprep::exporter
