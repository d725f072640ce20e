// Reader of the HDF5 model format, version 1 (ARCHITECTURE.md). Every object
// is checked for presence, shape, type and values before it enters the
// model; a defect gives bad_input naming the file and the dataset.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include "hdf5_handle.h"
#include "igaprep/core/error.h"
#include "igaprep/core/input_files.h"
#include "igaprep/export/hdf5_model.h"
#include "igaprep/spline/knot_vector.h"
#include "model_checks.h"

namespace igaprep::exporter {

namespace {
using detail::H5Handle;

class Reader {
 public:
  explicit Reader(std::string path) : path_(std::move(path)) {}

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

std::string patch_group_name(int i) {
  char name[32];
  std::snprintf(name, sizeof(name), "%06d", i);
  return name;
}

spline::MultiPatch read_model(Reader& r) {
  const hid_t root = r.root();
  spline::MultiPatch model;
  if (!r.has_attribute(root, "format")) r.bad("attribute /format", "missing: not an igaprep model file");
  const std::string format = r.string_scalar(root, "format", "/format");
  if (format != "igaprep-multipatch")
    r.bad("attribute /format", "is '" + format + "', expected 'igaprep-multipatch'");
  const int version = r.int_scalar(root, "format_version", "/format_version");
  if (version != 1)
    r.bad("attribute /format_version", "version " + std::to_string(version) + " is not supported (this igaprep reads version 1)");

  // Labels and materials first: patches, interfaces and boundaries index them.
  model.labels = r.read_strings(root, "labels", "/labels");
  const int nl = static_cast<int>(model.labels.size());
  {
    H5Handle mats = r.open_group(root, "materials", "/materials");
    const std::vector<std::string> names = r.read_strings(mats.get(), "name", "/materials/name");
    std::vector<hsize_t> dy, dp;
    const std::vector<double> young = r.read_doubles(mats.get(), "young_modulus", "/materials/young_modulus", &dy);
    const std::vector<double> poisson = r.read_doubles(mats.get(), "poisson_ratio", "/materials/poisson_ratio", &dp);
    r.expect_rank(dy, 1, "dataset /materials/young_modulus", "(" + std::to_string(names.size()) + ",)");
    r.expect_rank(dp, 1, "dataset /materials/poisson_ratio", "(" + std::to_string(names.size()) + ",)");
    if (young.size() != names.size())
      r.bad("dataset /materials/young_modulus", std::to_string(young.size()) + " entries but /materials/name has " + std::to_string(names.size()));
    if (poisson.size() != names.size())
      r.bad("dataset /materials/poisson_ratio", std::to_string(poisson.size()) + " entries but /materials/name has " + std::to_string(names.size()));
    for (size_t m = 0; m < names.size(); ++m) model.materials.push_back({names[m], young[m], poisson[m]});
  }
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

  if (r.has_link(root, "provenance")) {
    H5Handle prov = r.open_group(root, "provenance", "/provenance");
    if (r.has_attribute(prov.get(), "generator"))
      model.provenance_generator = r.string_scalar(prov.get(), "generator", "/provenance/generator");
    if (r.has_attribute(prov.get(), "case"))
      model.provenance_case = r.string_scalar(prov.get(), "case", "/provenance/case");
    if (r.has_attribute(prov.get(), "inputs"))
      model.provenance_inputs = r.string_scalar(prov.get(), "inputs", "/provenance/inputs");
  }
  return model;
}
}  // namespace

spline::MultiPatch read_hdf5_model(const std::string& path) {
  require_regular_file(path, "model file");
  detail::SilenceHdf5Errors quiet;
  Reader r(path);
  r.open();
  return read_model(r);
}

}  // namespace igaprep::exporter
