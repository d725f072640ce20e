// Reader of the Bezier-extraction model format, version 1
// (docs/hdf5-format.md): nothing is used before its counts, offsets,
// indices and shapes agree.
#include <string>
#include <vector>

#include "hdf5_reader.h"
#include "igaprep/export/hdf5_extraction.h"

namespace igaprep::exporter {

namespace {
using detail::H5Handle;
using Reader = detail::Hdf5Reader;

// A dataset of exactly `shape` (0 in shape: any length there).
void expect_shape(const Reader& r, const std::vector<hsize_t>& dims, const std::vector<hsize_t>& shape,
                  const std::string& full) {
  bool ok = dims.size() == shape.size();
  for (std::size_t d = 0; ok && d < dims.size(); ++d) ok = shape[d] == 0 || dims[d] == shape[d];
  if (!ok) r.bad("dataset " + full, "shape " + Reader::shape_text(dims) + ", expected " + Reader::shape_text(shape));
}
std::vector<long long> ints(const Reader& r, hid_t loc, const std::string& name, const std::string& full,
                            const std::vector<hsize_t>& shape) {
  std::vector<hsize_t> dims;
  std::vector<long long> v = r.read_ints(loc, name, full, &dims);
  expect_shape(r, dims, shape, full);
  return v;
}
std::vector<double> doubles(const Reader& r, hid_t loc, const std::string& name, const std::string& full,
                            const std::vector<hsize_t>& shape) {
  std::vector<hsize_t> dims;
  std::vector<double> v = r.read_doubles(loc, name, full, &dims);
  expect_shape(r, dims, shape, full);
  return v;
}

// Offsets of a CSR array: from 0, never decreasing, ending at `total`.
void check_offsets(const Reader& r, const std::vector<long long>& o, std::size_t total, const std::string& full) {
  if (o.empty() || o.front() != 0 || o.back() != static_cast<long long>(total))
    r.bad("dataset " + full, "must run from 0 to " + std::to_string(total));
  for (std::size_t i = 1; i < o.size(); ++i)
    if (o[i] < o[i - 1]) r.bad("dataset " + full, "decreases at entry " + std::to_string(i));
}

void read_operators(const Reader& r, spline::ExtractionModel& m) {
  H5Handle g = r.open_group(r.root(), "operators", "/operators");
  const std::vector<long long> shape = ints(r, g.get(), "shape", "/operators/shape", {0, 2});
  const hsize_t k = shape.size() / 2;
  const std::vector<long long> offsets = ints(r, g.get(), "offsets", "/operators/offsets", {k + 1});
  const std::vector<double> values = doubles(r, g.get(), "values", "/operators/values", {0});
  check_offsets(r, offsets, values.size(), "/operators/offsets");
  for (hsize_t i = 0; i < k; ++i) {
    const long long rows = shape[2 * i], cols = shape[2 * i + 1];
    if (rows < 1 || cols < 1 || rows * cols != offsets[i + 1] - offsets[i])
      r.bad("dataset /operators/shape", "operator " + std::to_string(i) + " is " + std::to_string(rows) + " x " +
                                            std::to_string(cols) + " but holds " + std::to_string(offsets[i + 1] - offsets[i]) + " values");
    Eigen::MatrixXd C(rows, cols);
    for (long long a = 0; a < rows; ++a)
      for (long long b = 0; b < cols; ++b) C(a, b) = values[static_cast<std::size_t>(offsets[i] + a * cols + b)];
    m.operators.push_back(std::move(C));
  }
}

void read_elements(const Reader& r, spline::ExtractionModel& m) {
  H5Handle g = r.open_group(r.root(), "elements", "/elements");
  const std::vector<long long> degrees = ints(r, g.get(), "degrees", "/elements/degrees", {0, 3});
  const hsize_t n = degrees.size() / 3;
  const std::vector<long long> material = ints(r, g.get(), "material", "/elements/material", {n});
  const std::vector<long long> offsets = ints(r, g.get(), "function_offsets", "/elements/function_offsets", {n + 1});
  const std::vector<long long> functions = ints(r, g.get(), "functions", "/elements/functions", {0});
  const std::vector<long long> extraction = ints(r, g.get(), "extraction", "/elements/extraction", {n});
  const std::vector<long long> patch = ints(r, g.get(), "patch", "/elements/patch", {n});
  const std::vector<long long> index = ints(r, g.get(), "index", "/elements/index", {n, 3});
  const std::vector<double> domain = doubles(r, g.get(), "domain", "/elements/domain", {n, 3, 2});
  check_offsets(r, offsets, functions.size(), "/elements/function_offsets");
  for (hsize_t e = 0; e < n; ++e) {
    const std::string name = "element " + std::to_string(e);
    spline::ExtractionElement el;
    long long bernstein = 1;
    for (int d = 0; d < 3; ++d) {
      const long long p = degrees[3 * e + static_cast<hsize_t>(d)];
      if (p < 0 || p > 30) r.bad("dataset /elements/degrees", name + ": degree " + std::to_string(p) + " outside 0..30");
      el.degrees[static_cast<std::size_t>(d)] = static_cast<int>(p);
      bernstein *= p + 1;
      el.index[static_cast<std::size_t>(d)] = static_cast<int>(index[3 * e + static_cast<hsize_t>(d)]);
      el.domain[static_cast<std::size_t>(d)] = {{domain[6 * e + 2 * static_cast<hsize_t>(d)], domain[6 * e + 2 * static_cast<hsize_t>(d) + 1]}};
      if (!(el.domain[static_cast<std::size_t>(d)][0] < el.domain[static_cast<std::size_t>(d)][1]))
        r.bad("dataset /elements/domain", name + ": an empty parameter interval");
    }
    if (material[e] < 0 || material[e] >= static_cast<long long>(m.materials.size()))
      r.bad("dataset /elements/material", name + ": material " + std::to_string(material[e]) + " but /materials has " +
                                              std::to_string(m.materials.size()));
    if (extraction[e] < 0 || extraction[e] >= static_cast<long long>(m.operators.size()))
      r.bad("dataset /elements/extraction", name + ": operator " + std::to_string(extraction[e]) + " but /operators has " +
                                                std::to_string(m.operators.size()));
    for (long long f = offsets[e]; f < offsets[e + 1]; ++f) {
      if (functions[static_cast<std::size_t>(f)] < 0 || functions[static_cast<std::size_t>(f)] >= m.function_count())
        r.bad("dataset /elements/functions", name + " names function " + std::to_string(functions[static_cast<std::size_t>(f)]));
      el.functions.push_back(static_cast<int>(functions[static_cast<std::size_t>(f)]));
    }
    const Eigen::MatrixXd& C = m.operators[static_cast<std::size_t>(extraction[e])];
    if (C.rows() != static_cast<Eigen::Index>(el.functions.size()) || C.cols() != bernstein)
      r.bad("dataset /elements/extraction", name + ": its operator is " + std::to_string(C.rows()) + " x " +
                                                std::to_string(C.cols()) + " for " + std::to_string(el.functions.size()) +
                                                " functions and " + std::to_string(bernstein) + " Bernstein polynomials");
    el.extraction = static_cast<int>(extraction[e]);
    el.material = static_cast<int>(material[e]);
    el.patch = static_cast<int>(patch[e]);
    m.elements.push_back(std::move(el));
  }
}

spline::ExtractionModel read_model(const Reader& r) {
  detail::expect_format(r, "igaprep-bezier-extraction");
  spline::ExtractionModel m;
  m.labels = r.read_strings(r.root(), "labels", "/labels");
  m.materials = detail::read_materials(r);
  const std::vector<double> cp = doubles(r, r.root(), "control_points", "/control_points", {0, 3});
  const std::vector<double> w = doubles(r, r.root(), "weights", "/weights", {cp.size() / 3});
  m.control_points.resize(static_cast<Eigen::Index>(cp.size() / 3), 3);
  m.weights.resize(static_cast<Eigen::Index>(w.size()));
  for (std::size_t i = 0; i < w.size(); ++i) {
    if (!(w[i] > 0.0)) r.bad("dataset /weights", "weight " + std::to_string(i) + " is not positive");
    m.weights[static_cast<Eigen::Index>(i)] = w[i];
    for (int c = 0; c < 3; ++c) m.control_points(static_cast<Eigen::Index>(i), c) = cp[3 * i + static_cast<std::size_t>(c)];
  }
  if (r.has_link(r.root(), "displacement")) {
    const std::vector<double> u = doubles(r, r.root(), "displacement", "/displacement", {cp.size() / 3, 3});
    m.displacement = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(u.data(), static_cast<Eigen::Index>(u.size() / 3), 3);
  }
  if (r.has_attribute(r.root(), "strain_energy") != r.has_attribute(r.root(), "max_displacement"))
    r.bad(r.has_attribute(r.root(), "strain_energy") ? "attribute /max_displacement" : "attribute /strain_energy",
          "missing (a solve result has both strain_energy and max_displacement)");
  if (r.has_attribute(r.root(), "strain_energy")) {
    m.has_solution = true;
    m.strain_energy = r.double_scalar(r.root(), "strain_energy", "/strain_energy");
    m.max_displacement = r.double_scalar(r.root(), "max_displacement", "/max_displacement");
  }
  read_operators(r, m);
  read_elements(r, m);
  auto read_faces = [&](const std::string& name, std::vector<spline::ExtractionBoundaryFace>& list) {
    const std::vector<long long> faces = ints(r, r.root(), name, "/" + name, {0, 3});
    for (std::size_t k = 0; k < faces.size() / 3; ++k) {
      const long long e = faces[3 * k], side = faces[3 * k + 1], label = faces[3 * k + 2];
      if (e < 0 || e >= static_cast<long long>(m.elements.size()) || side < 1 || side > 6 || label < 0 ||
          label >= static_cast<long long>(m.labels.size()))
        r.bad("dataset /" + name, "row " + std::to_string(k) + " names an element, side or label that does not exist");
      list.push_back({static_cast<int>(e), spline::Side(static_cast<int>(side)), static_cast<int>(label)});
    }
  };
  read_faces("boundary_faces", m.boundary_faces);
  if (r.has_link(r.root(), "interface_faces")) read_faces("interface_faces", m.interface_faces);
  detail::read_provenance(r, &m.provenance_generator, &m.provenance_case, &m.provenance_inputs);
  return m;
}

}  // namespace

bool is_hdf5_extraction(const std::string& path) {
  try {
    return detail::read_model_file(path, [](const Reader& r) {
      return r.has_attribute(r.root(), "format") &&
             r.string_scalar(r.root(), "format", "/format") == "igaprep-bezier-extraction";
    });
  } catch (const Error&) {
    return false;
  }
}

spline::ExtractionModel read_hdf5_extraction(const std::string& path) { return detail::read_model_file(path, read_model); }

}  // namespace igaprep::exporter
