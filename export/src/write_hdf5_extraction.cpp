// Writer of the Bezier-extraction model format, version 1
// (docs/hdf5-format.md): per-element data as CSR arrays.
#include <cstdint>
#include <vector>

#include "hdf5_writer.h"
#include "igaprep/core/atomic_file.h"
#include "igaprep/export/hdf5_extraction.h"

namespace igaprep::exporter {

namespace {
using detail::H5Handle;

void check_extraction_model(const spline::ExtractionModel& m, const std::string& path) {
  const auto fail = [&](const std::string& why) { throw bad_input("cannot write '" + path + "': " + why); };
  if (m.weights.size() != m.control_points.rows() || m.control_points.cols() != 3)
    fail("control points and weights do not match");
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    const spline::ExtractionElement& el = m.elements[e];
    const Eigen::Index bernstein = (el.degrees[0] + 1) * (el.degrees[1] + 1) * (el.degrees[2] + 1);
    if (el.extraction < 0 || el.extraction >= static_cast<int>(m.operators.size()))
      fail("element " + std::to_string(e) + " names operator " + std::to_string(el.extraction));
    const Eigen::MatrixXd& C = m.operators[static_cast<std::size_t>(el.extraction)];
    if (C.rows() != static_cast<Eigen::Index>(el.functions.size()) || C.cols() != bernstein)
      fail("element " + std::to_string(e) + "'s operator is not functions x Bernstein polynomials");
    for (const int f : el.functions)
      if (f < 0 || f >= m.function_count()) fail("element " + std::to_string(e) + " names function " + std::to_string(f));
    if (el.material < 0 || el.material >= static_cast<int>(m.materials.size()))
      fail("element " + std::to_string(e) + " has no material " + std::to_string(el.material));
  }
  if (m.displacement.size() > 0 && (m.displacement.rows() != m.function_count() || m.displacement.cols() != 3))
    fail("the displacement is not one (ux, uy, uz) per function");
  for (const auto* list : {&m.boundary_faces, &m.interface_faces})
    for (const spline::ExtractionBoundaryFace& f : *list)
      if (f.element < 0 || f.element >= static_cast<int>(m.elements.size()) || !f.side.valid() || f.label < 0 ||
          f.label >= static_cast<int>(m.labels.size()))
        fail("a boundary or interface face names an element, side or label that does not exist");
}

void write_elements(const detail::Hdf5Writer& w, hid_t root, const spline::ExtractionModel& m) {
  H5Handle g = w.create_group(root, "elements", "group /elements");
  const auto n = static_cast<hsize_t>(m.elements.size());
  std::vector<int> degrees, material, patch, index, functions, extraction;
  std::vector<std::int64_t> function_offsets{0};
  std::vector<double> domain;
  for (const spline::ExtractionElement& e : m.elements) {
    degrees.insert(degrees.end(), e.degrees.begin(), e.degrees.end());
    material.push_back(e.material);
    patch.push_back(e.patch);
    index.insert(index.end(), e.index.begin(), e.index.end());
    for (const auto& d : e.domain) domain.insert(domain.end(), d.begin(), d.end());
    functions.insert(functions.end(), e.functions.begin(), e.functions.end());
    function_offsets.push_back(static_cast<std::int64_t>(functions.size()));
    extraction.push_back(e.extraction);
  }
  const auto i32 = [&](const char* name, const std::vector<int>& v, std::vector<hsize_t> shape) {
    w.write_dataset(g.get(), name, std::string("dataset /elements/") + name, H5T_STD_I32LE, H5T_NATIVE_INT, shape, v.data());
  };
  const auto i64 = [&](const char* name, const std::vector<std::int64_t>& v) {
    w.write_dataset(g.get(), name, std::string("dataset /elements/") + name, H5T_STD_I64LE, H5T_NATIVE_INT64,
                    {static_cast<hsize_t>(v.size())}, v.data());
  };
  const auto f64 = [&](const char* name, const std::vector<double>& v, std::vector<hsize_t> shape) {
    w.write_dataset(g.get(), name, std::string("dataset /elements/") + name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, shape,
                    v.data());
  };
  i32("degrees", degrees, {n, 3});
  i32("material", material, {n});
  i64("function_offsets", function_offsets);
  i32("functions", functions, {static_cast<hsize_t>(functions.size())});
  i32("extraction", extraction, {n});
  i32("patch", patch, {n});
  i32("index", index, {n, 3});
  f64("domain", domain, {n, 3, 2});
}

// The distinct operators, each dense and row-major, one after the other.
void write_operators(const detail::Hdf5Writer& w, hid_t root, const spline::ExtractionModel& m) {
  H5Handle g = w.create_group(root, "operators", "group /operators");
  std::vector<int> shape;
  std::vector<std::int64_t> offsets{0};
  std::vector<double> values;
  for (const Eigen::MatrixXd& C : m.operators) {
    shape.insert(shape.end(), {static_cast<int>(C.rows()), static_cast<int>(C.cols())});
    const std::vector<double> v = detail::row_major(C);
    values.insert(values.end(), v.begin(), v.end());
    offsets.push_back(static_cast<std::int64_t>(values.size()));
  }
  w.write_dataset(g.get(), "shape", "dataset /operators/shape", H5T_STD_I32LE, H5T_NATIVE_INT,
                  {static_cast<hsize_t>(m.operators.size()), 2}, shape.data());
  w.write_dataset(g.get(), "offsets", "dataset /operators/offsets", H5T_STD_I64LE, H5T_NATIVE_INT64,
                  {static_cast<hsize_t>(offsets.size())}, offsets.data());
  w.write_dataset(g.get(), "values", "dataset /operators/values", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                  {static_cast<hsize_t>(values.size())}, values.data());
}

void write_file(const spline::ExtractionModel& m, const std::string& path, const std::string& temp) {
  detail::Hdf5Writer w(path);
  H5Handle file = w.create_file(temp, "igaprep-bezier-extraction", 1);
  const hid_t root = file.get();
  const std::vector<double> cp = detail::row_major(m.control_points);
  w.write_dataset(root, "control_points", "dataset /control_points", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                  {static_cast<hsize_t>(m.control_points.rows()), 3}, cp.data());
  w.write_dataset(root, "weights", "dataset /weights", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                  {static_cast<hsize_t>(m.weights.size())}, m.weights.data());
  if (m.displacement.size() > 0) {
    const std::vector<double> u = detail::row_major(m.displacement);
    w.write_dataset(root, "displacement", "dataset /displacement", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                    {static_cast<hsize_t>(m.displacement.rows()), 3}, u.data());
  }
  if (m.has_solution) {
    w.double_attribute(root, "strain_energy", "attribute /strain_energy", m.strain_energy);
    w.double_attribute(root, "max_displacement", "attribute /max_displacement", m.max_displacement);
  }
  write_elements(w, root, m);
  write_operators(w, root, m);
  auto write_faces = [&](const char* name, const std::vector<spline::ExtractionBoundaryFace>& list) {
    std::vector<int> faces;
    for (const spline::ExtractionBoundaryFace& f : list) faces.insert(faces.end(), {f.element, f.side.index(), f.label});
    w.write_dataset(root, name, std::string("dataset /") + name, H5T_STD_I32LE, H5T_NATIVE_INT, {static_cast<hsize_t>(list.size()), 3},
                    faces.data());
  };
  write_faces("boundary_faces", m.boundary_faces);
  if (!m.interface_faces.empty()) write_faces("interface_faces", m.interface_faces);
  w.write_strings(root, "labels", "dataset /labels", m.labels);
  detail::write_materials(w, root, m.materials);
  detail::write_provenance(w, root, m.provenance_generator, m.provenance_case, m.provenance_inputs);
  w.check_status(H5Fflush(root, H5F_SCOPE_GLOBAL), "flush");
}

}  // namespace

void write_hdf5_extraction(const spline::ExtractionModel& model, const std::string& path) {
  check_extraction_model(model, path);
  detail::SilenceHdf5Errors quiet;
  AtomicPath target(path);
  write_file(model, path, target.temp_path());
  target.commit();
}

}  // namespace igaprep::exporter
