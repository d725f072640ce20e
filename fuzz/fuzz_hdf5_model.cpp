// libFuzzer target: exporter::read_hdf5_model on valid model files whose
// datasets and attributes the input mutates through the HDF5 API (values
// overwritten, shapes changed, objects deleted), so that the fuzzing reaches
// igaprep's reader rather than the HDF5 library's own file parser. The seed
// is a two-patch rational model with an interface, labels, materials, a
// solution and provenance, written once per process. Every input must end in
// a model or an igaprep::Error of kind BadInput; anything else is a finding.
// Built by scripts/fuzz.sh.
#include <hdf5.h>
#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "igaprep/core/error.h"
#include "igaprep/export/hdf5_model.h"
#include "igaprep/spline/multipatch.h"

namespace {

using igaprep::spline::MultiPatch;
using igaprep::spline::Patch;

Patch unit_cube(double x0) {
  Patch p;
  p.degrees = {1, 1, 1};
  for (auto& k : p.knots) k = {0, 0, 1, 1};
  p.control_points.resize(8, 3);
  for (int i = 0; i < 8; ++i) p.control_points.row(i) << x0 + (i & 1), (i >> 1) & 1, (i >> 2) & 1;
  p.weights = Eigen::VectorXd::Ones(8);
  p.displacement = Eigen::MatrixXd::Constant(8, 3, 0.01);
  return p;
}

MultiPatch seed_model() {
  MultiPatch m;
  m.patches = {unit_cube(0.0), unit_cube(1.0)};
  m.patches[1].material = 1;
  m.materials = {{"steel", 200e3, 0.3}, {"bone", 17e3, 0.3}};
  m.labels = {"outer", "inner"};
  igaprep::spline::Interface in;
  in.patch_a = 0;
  in.side_a = 2;  // u = 1
  in.patch_b = 1;
  in.side_b = 1;  // u = 0
  in.surface = 1;
  m.interfaces = {in};
  for (int p = 0; p < 2; ++p)
    for (int s = 1; s <= 6; ++s)
      if (!(p == 0 && s == 2) && !(p == 1 && s == 1)) m.boundaries.push_back({p, s, s == 5 ? 1 : 0});
  m.has_solution = true;
  m.strain_energy = 1.5;
  m.max_displacement = 0.01;
  m.provenance_generator = "fuzz";
  m.provenance_case = "{}";
  m.provenance_inputs = "[]";
  return m;
}

const std::string& seed_bytes() {
  static const std::string bytes = [] {
    const std::string path = "/dev/shm/igaprep-fuzz-seed-" + std::to_string(::getpid()) + ".h5";
    igaprep::exporter::write_hdf5_model(seed_model(), path);
    std::ifstream in(path, std::ios::binary);
    std::string b((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::remove(path.c_str());
    return b;
  }();
  return bytes;
}

// The input, read a byte at a time (zeros once it runs out).
struct Bytes {
  const std::uint8_t* data;
  std::size_t size, at = 0;
  bool done() const { return at >= size; }
  std::uint8_t next() { return at < size ? data[at++] : 0; }
};

struct Objects {
  std::vector<std::string> datasets;
  std::vector<std::pair<std::string, std::string>> attributes;  // object path, attribute name
};

herr_t collect_attribute(hid_t, const char* name, const H5A_info_t*, void* data) {
  auto* out = static_cast<std::pair<Objects*, std::string>*>(data);
  out->first->attributes.emplace_back(out->second, name);
  return 0;
}

herr_t collect_object(hid_t root, const char* name, const H5O_info_t* info, void* data) {
  auto* objects = static_cast<Objects*>(data);
  if (info->type == H5O_TYPE_DATASET) objects->datasets.push_back(name);
  std::pair<Objects*, std::string> where(objects, name);
  H5Aiterate_by_name(root, name, H5_INDEX_NAME, H5_ITER_INC, nullptr, collect_attribute, &where, H5P_DEFAULT);
  return 0;
}

// A buffer of `count` elements of `type` filled from the input; for
// variable-length strings, pointers to strings made of input bytes.
struct Filled {
  std::vector<unsigned char> raw;
  std::vector<std::string> strings;
  std::vector<const char*> pointers;
  const void* data() const { return pointers.empty() ? static_cast<const void*>(raw.data()) : pointers.data(); }
};

Filled fill(hid_t type, hsize_t count, Bytes& in) {
  Filled f;
  if (H5Tis_variable_str(type) > 0) {
    for (hsize_t i = 0; i < count; ++i) {
      std::string s;
      for (int n = in.next() % 16; n > 0; --n) s.push_back(static_cast<char>(in.next() | 1));
      f.strings.push_back(s);
    }
    for (const auto& s : f.strings) f.pointers.push_back(s.c_str());
    return f;
  }
  f.raw.resize(static_cast<std::size_t>(count * H5Tget_size(type)));
  for (auto& b : f.raw) b = in.next();
  return f;
}

hsize_t element_count(hid_t space) {
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  return n > 0 ? static_cast<hsize_t>(n) : 0;
}

void overwrite_dataset(hid_t file, const std::string& path, Bytes& in) {
  const hid_t d = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  if (d < 0) return;
  const hid_t type = H5Dget_type(d), space = H5Dget_space(d);
  const hsize_t n = std::min<hsize_t>(element_count(space), 4096);
  if (n == element_count(space) && n > 0) {
    const Filled f = fill(type, n, in);
    H5Dwrite(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, f.data());
  }
  H5Sclose(space);
  H5Tclose(type);
  H5Dclose(d);
}

// The dataset replaced by one of the same type and rank with other extents.
void reshape_dataset(hid_t file, const std::string& path, Bytes& in) {
  const hid_t d = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  if (d < 0) return;
  const hid_t type = H5Dget_type(d), space = H5Dget_space(d);
  const int rank = std::max(1, H5Sget_simple_extent_ndims(space));
  H5Sclose(space);
  H5Dclose(d);
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  hsize_t total = 1;
  for (auto& x : dims) total *= (x = in.next() % 12);
  H5Ldelete(file, path.c_str(), H5P_DEFAULT);
  const hid_t s = H5Screate_simple(rank, dims.data(), nullptr);
  const hid_t nd = H5Dcreate2(file, path.c_str(), type, s, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (nd >= 0) {
    if (total > 0) {
      const Filled f = fill(type, total, in);
      H5Dwrite(nd, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, f.data());
    }
    H5Dclose(nd);
  }
  H5Sclose(s);
  H5Tclose(type);
}

void overwrite_attribute(hid_t file, const std::pair<std::string, std::string>& at, Bytes& in) {
  const hid_t a = H5Aopen_by_name(file, at.first.c_str(), at.second.c_str(), H5P_DEFAULT, H5P_DEFAULT);
  if (a < 0) return;
  const hid_t type = H5Aget_type(a), space = H5Aget_space(a);
  const hsize_t n = std::min<hsize_t>(element_count(space), 256);
  if (n == element_count(space) && n > 0) {
    const Filled f = fill(type, n, in);
    H5Awrite(a, type, f.data());
  }
  H5Sclose(space);
  H5Tclose(type);
  H5Aclose(a);
}

void mutate(hid_t file, Bytes& in) {
  Objects objects;
  H5Ovisit2(file, H5_INDEX_NAME, H5_ITER_INC, collect_object, &objects, H5O_INFO_BASIC);
  for (int op = 0; op < 4 && !in.done(); ++op) {
    const int kind = in.next() % 5;
    const std::size_t pick = in.next();
    if (kind <= 2 && !objects.datasets.empty()) {
      const std::string& path = objects.datasets[pick % objects.datasets.size()];
      if (kind == 0) overwrite_dataset(file, path, in);
      else if (kind == 1) reshape_dataset(file, path, in);
      else H5Ldelete(file, path.c_str(), H5P_DEFAULT);
    } else if (kind >= 3 && !objects.attributes.empty()) {
      const auto& at = objects.attributes[pick % objects.attributes.size()];
      if (kind == 3) overwrite_attribute(file, at, in);
      else H5Adelete_by_name(file, at.first.c_str(), at.second.c_str(), H5P_DEFAULT);
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // the reader's messages, not HDF5's stack
  // HDF5's free lists unbounded, so that its large blocks (the metadata
  // cache of every open file) are reused: freed to the sanitizer's allocator
  // they came back as fresh pages at each open, 90 executions per second.
  H5set_free_list_limits(-1, -1, -1, -1, -1, -1);
  seed_bytes();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string path = "/dev/shm/igaprep-fuzz-" + std::to_string(::getpid()) + ".h5";
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << seed_bytes();
  }
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  if (file < 0) return 0;
  Bytes in{data, size};
  mutate(file, in);
  H5Fclose(file);
  try {
    const MultiPatch m = igaprep::exporter::read_hdf5_model(path);
    (void)m;
  } catch (const igaprep::Error& e) {
    if (e.kind() == igaprep::ErrorKind::Internal) __builtin_trap();
  }
  return 0;
}
