#include "igaprep/iga_check/model_picture.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "igaprep/core/text.h"
#include "igaprep/spline/bezier_extraction.h"
#include "igaprep/spline/evaluate.h"

namespace igaprep::iga_check {

namespace {

struct Face {
  std::array<Eigen::Vector3d, 4> corners;
  int patch = 0;
  int material = 0;
};

// The element faces on the model's labelled sides, corners in order round
// the face.
std::vector<Face> boundary_faces(const spline::MultiPatch& mp) {
  std::vector<Face> out;
  for (const spline::BoundarySide& b : mp.boundaries) {
    const spline::Patch& p = mp.patches[static_cast<std::size_t>(b.patch)];
    const spline::PatchExtraction ex = spline::bezier_extraction(p);
    const int n = b.side.direction(), a = n == 0 ? 1 : 0, c = n == 2 ? 1 : 2;
    const std::vector<double>& A = ex.dirs[static_cast<std::size_t>(a)].breaks;
    const std::vector<double>& C = ex.dirs[static_cast<std::size_t>(c)].breaks;
    const std::vector<double>& N = ex.dirs[static_cast<std::size_t>(n)].breaks;
    const double fixed = b.side.parameter() ? N.back() : N.front();
    for (std::size_t j = 0; j + 1 < C.size(); ++j)
      for (std::size_t i = 0; i + 1 < A.size(); ++i) {
        Face f{{}, b.patch, p.material};
        const double us[4] = {A[i], A[i + 1], A[i + 1], A[i]}, vs[4] = {C[j], C[j], C[j + 1], C[j + 1]};
        for (int k = 0; k < 4; ++k) {
          Eigen::Vector3d xi;
          xi[n] = fixed;
          xi[a] = us[k];
          xi[c] = vs[k];
          f.corners[static_cast<std::size_t>(k)] = spline::evaluate_point(p, xi);
        }
        out.push_back(f);
      }
  }
  return out;
}

// Red (q <= 0), yellow (0.5), blue (1), times the shade.
std::string colour(double q, double shade, bool known) {
  Eigen::Vector3d rgb(0.7, 0.7, 0.7);
  if (known) {
    const double t = std::clamp(q, 0.0, 1.0);
    rgb = t < 0.5 ? Eigen::Vector3d(0.85, 0.15 + 1.4 * t, 0.1) : Eigen::Vector3d(0.85 - 1.5 * (t - 0.5), 0.85 - 0.7 * (t - 0.5), 0.1 + 1.6 * (t - 0.5));
  }
  rgb *= shade;
  return text("rgb(%d,%d,%d)", static_cast<int>(255 * rgb[0]), static_cast<int>(255 * rgb[1]), static_cast<int>(255 * rgb[2]));
}

// A palette of twelve distinct colours by index, times the shade.
std::string palette(int index, double shade) {
  static const int rgb[12][3] = {{31, 119, 180}, {255, 127, 14}, {44, 160, 44},  {214, 39, 40},
                                 {148, 103, 189}, {140, 86, 75}, {227, 119, 194}, {127, 127, 127},
                                 {188, 189, 34},  {23, 190, 207}, {174, 199, 232}, {255, 187, 120}};
  const int* c = rgb[((index % 12) + 12) % 12];
  return text("rgb(%d,%d,%d)", static_cast<int>(c[0] * shade), static_cast<int>(c[1] * shade),
              static_cast<int>(c[2] * shade));
}

}  // namespace

std::string model_picture_svg(const spline::MultiPatch& mp, const std::vector<double>& patch_min_scaled_jacobian,
                              const std::vector<bool>& patch_failed, PictureColour colouring,
                              const std::vector<PictureMark>& marks) {
  const std::vector<Face> faces = boundary_faces(mp);
  if (faces.empty()) return "";
  const Eigen::Vector3d view = Eigen::Vector3d(1.0, -1.0, 0.6).normalized();  // towards the viewer
  const Eigen::Vector3d right = Eigen::Vector3d::UnitZ().cross(view).normalized();
  const Eigen::Vector3d up = view.cross(right);
  const Eigen::Vector3d light = (view + 0.5 * up).normalized();
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(INFINITY), hi = -lo;
  for (const Face& f : faces)
    for (const Eigen::Vector3d& x : f.corners) {
      const Eigen::Vector2d s(x.dot(right), -x.dot(up));
      lo = lo.cwiseMin(s);
      hi = hi.cwiseMax(s);
    }
  const double width = 640.0, scale = width / std::max(hi[0] - lo[0], 1e-300);
  const double height = std::max(1.0, (hi[1] - lo[1]) * scale);
  std::vector<std::size_t> order(faces.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  auto depth = [&](const Face& f) { return (f.corners[0] + f.corners[1] + f.corners[2] + f.corners[3]).dot(view); };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return depth(faces[a]) < depth(faces[b]); });
  std::ostringstream svg;
  const char* id = colouring == PictureColour::patch      ? "model-picture-by-patch"
                   : colouring == PictureColour::material ? "model-picture-by-material"
                                                          : "model-picture";
  svg << "<svg id=\"" << id << "\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" << static_cast<int>(width + 20)
      << "\" height=\"" << static_cast<int>(height + 20) << "\" viewBox=\"-10 -10 " << static_cast<int>(width + 20) << " "
      << static_cast<int>(height + 20) << "\">\n";
  for (const std::size_t i : order) {
    const Face& f = faces[i];
    const Eigen::Vector3d normal = (f.corners[2] - f.corners[0]).cross(f.corners[3] - f.corners[1]);
    const double shade = normal.norm() > 0.0 ? 0.45 + 0.55 * std::abs(normal.normalized().dot(light)) : 0.7;
    const auto p = static_cast<std::size_t>(f.patch);
    const bool known = p < patch_min_scaled_jacobian.size(), failed = p < patch_failed.size() && patch_failed[p];
    svg << "<polygon points=\"";
    for (const Eigen::Vector3d& x : f.corners)
      svg << text("%.1f,%.1f ", (x.dot(right) - lo[0]) * scale, (-x.dot(up) - lo[1]) * scale);
    const std::string fill = colouring == PictureColour::patch      ? palette(f.patch, shade)
                             : colouring == PictureColour::material ? palette(f.material, shade)
                                                                    : colour(known ? patch_min_scaled_jacobian[p] : 0.0, shade, known);
    svg << "\" fill=\"" << fill << "\" stroke=\""
        << (failed ? "#d00000" : "#333") << "\" stroke-width=\"" << (failed ? "1.5" : "0.3") << "\"/>\n";
  }
  for (const PictureMark& m : marks) {
    const double x = (m.at.dot(right) - lo[0]) * scale, y = (-m.at.dot(up) - lo[1]) * scale;
    svg << text("<circle class=\"mark\" cx=\"%.1f\" cy=\"%.1f\" r=\"7\" fill=\"none\" stroke=\"#000\" stroke-width=\"2\"/>", x, y)
        << text("<text class=\"a\" x=\"%.1f\" y=\"%.1f\">", x + 8.0, y - 8.0) << m.label << "</text>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace igaprep::iga_check
