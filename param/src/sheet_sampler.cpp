#include "igaprep/param/sheet_sampler.h"

#include <Eigen/Geometry>

#include <sstream>
#include <vector>

#include "igaprep/core/error.h"

namespace igaprep::param {

SheetSampler::SheetSampler(const mesh::TriMesh& sheet, const Eigen::MatrixXd& uv, int smoothing_rounds)
    : sheet_(sheet), uv_(uv) {
  const auto& V = sheet.V;
  const auto& F = sheet.F;
  if (uv.rows() != V.rows() || uv.cols() != 2 || F.rows() == 0)
    throw bad_input("sheet sampler: need a non-empty sheet with one (u, v) per vertex");
  normal_ = Eigen::MatrixXd::Zero(V.rows(), 3);
  du_ = Eigen::MatrixXd::Zero(V.rows(), 3);
  dv_ = Eigen::MatrixXd::Zero(V.rows(), 3);
  Eigen::VectorXd weight = Eigen::VectorXd::Zero(V.rows());
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const int a = F(f, 0), b = F(f, 1), c = F(f, 2);
    const Eigen::Vector3d e1 = V.row(b) - V.row(a), e2 = V.row(c) - V.row(a);
    const Eigen::Vector2d t1 = uv.row(b) - uv.row(a), t2 = uv.row(c) - uv.row(a);
    const double det = t1.x() * t2.y() - t1.y() * t2.x();
    if (!(det > 0.0)) {
      std::ostringstream why;
      why << "sheet sampler: (u, v) triangle " << f << " is not positively oriented (det " << det << ", corners ("
          << uv.row(a) << "), (" << uv.row(b) << "), (" << uv.row(c) << "))";
      throw bad_input(why.str());
    }
    // [e1 e2] = [Xu Xv] [t1 t2]  =>  [Xu Xv] = [e1 e2] [t1 t2]^-1
    const Eigen::Vector3d Xu = (e1 * t2.y() - e2 * t1.y()) / det;
    const Eigen::Vector3d Xv = (-e1 * t2.x() + e2 * t1.x()) / det;
    const Eigen::Vector3d n = e1.cross(e2);  // length = 2 x area: area-weighted
    const double area = 0.5 * n.norm();
    for (int v : {a, b, c}) {
      normal_.row(v) += n.transpose();
      du_.row(v) += area * Xu.transpose();
      dv_.row(v) += area * Xv.transpose();
      weight(v) += area;
    }
  }
  for (Eigen::Index v = 0; v < V.rows(); ++v) {
    if (weight(v) > 0.0) {
      normal_.row(v).normalize();
      du_.row(v) /= weight(v);
      dv_.row(v) /= weight(v);
    }
  }
  // A few rounds of area-weighted averaging over the one-ring: the sheet is
  // the zero set of a P1 field, and a vertex with one or two thin triangles
  // (at a corner of the domain) can have a normal several degrees off.
  for (int round = 0; round < smoothing_rounds; ++round) {
    Eigen::MatrixXd n = Eigen::MatrixXd::Zero(V.rows(), 3), a = n, b = n;
    for (Eigen::Index f = 0; f < F.rows(); ++f) {
      const Eigen::Vector3d e1 = V.row(F(f, 1)) - V.row(F(f, 0)), e2 = V.row(F(f, 2)) - V.row(F(f, 0));
      const double area = 0.5 * e1.cross(e2).norm();
      Eigen::RowVector3d fn = Eigen::RowVector3d::Zero(), fa = fn, fb = fn;
      for (int k = 0; k < 3; ++k) fn += normal_.row(F(f, k)), fa += du_.row(F(f, k)), fb += dv_.row(F(f, k));
      for (int k = 0; k < 3; ++k) {
        n.row(F(f, k)) += area * fn / 3.0;
        a.row(F(f, k)) += area * fa / 3.0;
        b.row(F(f, k)) += area * fb / 3.0;
      }
    }
    for (Eigen::Index v = 0; v < V.rows(); ++v) {
      if (!(weight(v) > 0.0)) continue;
      normal_.row(v) = n.row(v).normalized();
      du_.row(v) = a.row(v) / weight(v);
      dv_.row(v) = b.row(v) / weight(v);
    }
  }
  // "Nearest triangle" queries in (u, v): the (u, v) triangles as flat 3D ones.
  Eigen::MatrixXd flat = Eigen::MatrixXd::Zero(uv.rows(), 3);
  flat.leftCols(2) = uv;
  flat_ = std::make_unique<SurfaceProjector>(flat, F);
}

SheetSampler::~SheetSampler() = default;

SheetPoint SheetSampler::at(const Eigen::Vector2d& q) const {
  int f = -1;
  const Eigen::Vector2d p = flat_->closest(Eigen::Vector3d(q.x(), q.y(), 0.0), &f).head<2>();
  const int a = sheet_.F(f, 0), b = sheet_.F(f, 1), c = sheet_.F(f, 2);
  const Eigen::Vector2d t1 = uv_.row(b) - uv_.row(a), t2 = uv_.row(c) - uv_.row(a), r = p - uv_.row(a).transpose();
  const double det = t1.x() * t2.y() - t1.y() * t2.x();
  const double lb = (r.x() * t2.y() - r.y() * t2.x()) / det, lc = (t1.x() * r.y() - t1.y() * r.x()) / det;
  const double la = 1.0 - lb - lc;
  SheetPoint s;
  s.triangle = f;
  s.bary = Eigen::Vector3d(la, lb, lc);
  s.position = la * sheet_.V.row(a) + lb * sheet_.V.row(b) + lc * sheet_.V.row(c);
  s.normal = (la * normal_.row(a) + lb * normal_.row(b) + lc * normal_.row(c)).normalized();
  s.du = la * du_.row(a) + lb * du_.row(b) + lc * du_.row(c);
  s.dv = la * dv_.row(a) + lb * dv_.row(b) + lc * dv_.row(c);
  return s;
}

}  // namespace igaprep::param
