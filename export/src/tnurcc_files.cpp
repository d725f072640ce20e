#include "igaprep/export/tnurcc_files.h"

#include <sstream>
#include <string>
#include <vector>

#include "igaprep/core/error.h"
#include "number_text.h"
#include "vtu_arrays.h"

namespace igaprep::exporter {

void write_cage_obj(const spline::Cage& cage, std::ostream& out) {
  out << "# igaprep T-NURCC cage: " << cage.points.rows() << " vertices, " << cage.faces.size() << " quads\n";
  for (int v = 0; v < cage.points.rows(); ++v)
    out << "v " << detail::exact(cage.points(v, 0)) << ' ' << detail::exact(cage.points(v, 1)) << ' '
        << detail::exact(cage.points(v, 2)) << '\n';
  for (const auto& f : cage.faces) out << "f " << f[0] + 1 << ' ' << f[1] + 1 << ' ' << f[2] + 1 << ' ' << f[3] + 1 << '\n';
  for (const auto& e : cage.edges)
    if (e.sharpness > 0.0)
      out << "t crease 2/1/0 " << e.vertices[0] << ' ' << e.vertices[1] << ' ' << detail::exact(e.sharpness) << '\n';
}

namespace {

[[noreturn]] void bad_line(int line, const std::string& text, const std::string& why) {
  throw bad_input("cage OBJ line " + std::to_string(line) + " ('" + text + "'): " + why);
}

int face_index(const std::string& token, int vertices, int line, const std::string& text) {
  const int i = std::stoi(token.substr(0, token.find('/')));
  const int v = i > 0 ? i - 1 : vertices + i;  // negative: relative to the end
  if (v < 0 || v >= vertices) bad_line(line, text, "vertex " + token + " does not exist");
  return v;
}

}  // namespace

spline::Cage read_cage_obj(std::istream& in) {
  std::vector<Eigen::Vector3d> points;
  spline::Cage cage;
  struct Crease {
    int a, b;
    double sharpness;
  };
  std::vector<Crease> creases;
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    std::istringstream ls(text);
    std::string key;
    if (!(ls >> key) || key[0] == '#') continue;
    try {
      if (key == "v") {
        Eigen::Vector3d p;
        if (!(ls >> p[0] >> p[1] >> p[2])) bad_line(line, text, "a vertex needs three numbers");
        points.push_back(p);
      } else if (key == "f") {
        std::vector<int> f;
        for (std::string tok; ls >> tok;) f.push_back(face_index(tok, static_cast<int>(points.size()), line, text));
        if (f.size() != 4) bad_line(line, text, "a cage face must be a quad");
        cage.faces.push_back({{f[0], f[1], f[2], f[3]}});
      } else if (key == "t") {
        std::string tag, counts;
        Crease c{};
        if (!(ls >> tag) || tag != "crease") continue;  // other tags (corner, ...) are not read
        if (!(ls >> counts >> c.a >> c.b >> c.sharpness) || counts != "2/1/0")
          bad_line(line, text, "a crease tag is 't crease 2/1/0 a b sharpness'");
        creases.push_back(c);
      }
    } catch (const std::logic_error&) {
      bad_line(line, text, "not a number");
    }
  }
  cage.points.resize(static_cast<int>(points.size()), 3);
  for (size_t v = 0; v < points.size(); ++v) cage.points.row(static_cast<int>(v)) = points[v].transpose();
  spline::build_cage_edges(cage);
  for (const Crease& c : creases) {
    bool found = false;
    for (auto& e : cage.edges)
      if ((e.vertices[0] == c.a && e.vertices[1] == c.b) || (e.vertices[0] == c.b && e.vertices[1] == c.a)) {
        e.sharpness = c.sharpness;
        found = true;
      }
    if (!found)
      throw bad_input("cage OBJ: crease (" + std::to_string(c.a) + ", " + std::to_string(c.b) + ") is not an edge");
  }
  return cage;
}

void write_cage_intervals(const spline::Cage& cage, std::ostream& out) {
  out << "{\"format\": \"igaprep-tnurcc-intervals\", \"version\": 1, \"edges\": [";
  for (size_t i = 0; i < cage.edges.size(); ++i) {
    const auto& e = cage.edges[i];
    out << (i ? ",\n  " : "\n  ") << '[' << e.vertices[0] << ", " << e.vertices[1] << ", "
        << detail::exact(e.interval) << ']';
  }
  out << "\n]}\n";
}

void write_limit_vtu(const spline::Cage& cage, int per_face, std::ostream& out, const spline::LimitOptions& options) {
  if (per_face < 1) throw bad_input("limit VTU: per_face must be >= 1");
  const int n = per_face + 1;
  const std::vector<spline::LimitLocation> at = spline::face_grid(cage, n, true);
  spline::LimitOptions with_curvature = options;
  with_curvature.second_derivatives = true;
  const spline::LimitValues v = spline::limit_values(spline::limit_stencils(cage, at, with_curvature), cage.points);
  std::vector<double> points, normals, curvature(v.mean_curvature.data(), v.mean_curvature.data() + v.mean_curvature.size());
  for (int i = 0; i < v.point.rows(); ++i)
    for (int d = 0; d < 3; ++d) {
      points.push_back(v.point(i, d));
      normals.push_back(v.normal(i, d));
    }
  std::vector<int64_t> connectivity, offsets;
  std::vector<uint8_t> types;
  std::vector<int32_t> face;
  for (size_t f = 0; f < cage.faces.size(); ++f)
    for (int j = 0; j + 1 < n; ++j)
      for (int i = 0; i + 1 < n; ++i) {
        const int64_t a = static_cast<int64_t>(f) * n * n + i + n * j;
        connectivity.insert(connectivity.end(), {a, a + 1, a + 1 + n, a + n});
        offsets.push_back(static_cast<int64_t>(connectivity.size()));
        types.push_back(9);  // VTK_QUAD
        face.push_back(static_cast<int32_t>(f));
      }
  detail::vtu_header(out, at.size(), types.size());
  detail::ArrayWriter w(out, true);
  out << "   <PointData Normals=\"Normals\" Scalars=\"MeanCurvature\">\n";
  w.array("Float64", "Normals", 3, normals, "    ");
  w.array("Float64", "MeanCurvature", 1, curvature, "    ");
  out << "   </PointData>\n   <CellData>\n";
  w.array("Int32", "face", 1, face, "    ");
  detail::vtu_points_cells_and_end(out, w, points, connectivity, offsets, types);
}

}  // namespace igaprep::exporter
