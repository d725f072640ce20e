#include "stage_validation.h"

#include <algorithm>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <limits>
#include <map>
#include <set>

#include "igaprep/core/error.h"
#include "igaprep/export/hdf5_model.h"
#include "igaprep/iga_check/elasticity_solve.h"
#include "igaprep/iga_check/manufactured_study.h"
#include "stage_timer.h"

namespace igaprep::cli {

namespace {

// Mean of the control points of a patch side (sides 1..6: u0, u1, v0, v1, w0, w1).
Eigen::Vector3d side_centre(const spline::Patch& p, int side) {
  const int d = (side - 1) / 2;
  const int fixed = (side % 2 == 1) ? 0 : p.count(d) - 1;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int n = 0;
  for (int k = 0; k < p.count(2); ++k)
    for (int j = 0; j < p.count(1); ++j)
      for (int i = 0; i < p.count(0); ++i) {
        const int ijk[3] = {i, j, k};
        if (ijk[d] != fixed) continue;
        sum += p.control_points.row(p.index(i, j, k)).transpose();
        ++n;
      }
  return n > 0 ? Eigen::Vector3d(sum / n) : sum;
}

bool in_box(const Eigen::Vector3d& x, const std::array<Eigen::Vector3d, 2>& box) {
  return (x.array() >= box[0].array()).all() && (x.array() <= box[1].array()).all();
}

int min_degree(const spline::MultiPatch& mp) {
  int p = std::numeric_limits<int>::max();
  for (const auto& patch : mp.patches)
    for (int d : patch.degrees) p = std::min(p, d);
  return mp.patches.empty() ? 0 : p;
}

}  // namespace

spline::MultiPatch validation_submodel(const spline::MultiPatch& mp, const std::vector<int>& patches) {
  std::map<int, int> new_index;
  for (int p : patches) {
    if (p < 0 || p >= static_cast<int>(mp.patches.size()) || new_index.count(p))
      throw internal_error("validation_submodel: bad or repeated patch index " + std::to_string(p));
    const int next = static_cast<int>(new_index.size());
    new_index[p] = next;
  }
  spline::MultiPatch sub;
  sub.labels = mp.labels;
  sub.materials = mp.materials;
  sub.patches.resize(patches.size());
  for (const auto& [old, now] : new_index) {
    sub.patches[now] = mp.patches[old];
    sub.patches[now].displacement.resize(0, 0);
  }
  std::set<std::pair<int, int>> covered;
  for (const auto& itf : mp.interfaces) {
    auto a = new_index.find(itf.patch_a), b = new_index.find(itf.patch_b);
    if (a == new_index.end() || b == new_index.end()) continue;
    spline::Interface i = itf;
    i.patch_a = a->second;
    i.patch_b = b->second;
    sub.interfaces.push_back(i);
    covered.insert({i.patch_a, i.side_a});
    covered.insert({i.patch_b, i.side_b});
  }
  for (const auto& bs : mp.boundaries) {
    auto a = new_index.find(bs.patch);
    if (a == new_index.end()) continue;
    spline::BoundarySide s = bs;
    s.patch = a->second;
    sub.boundaries.push_back(s);
    covered.insert({s.patch, s.side});
  }
  int cut_label = -1;
  for (int p = 0; p < static_cast<int>(sub.patches.size()); ++p)
    for (int s = 1; s <= 6; ++s) {
      if (covered.count({p, s})) continue;
      if (cut_label < 0) {
        cut_label = static_cast<int>(sub.labels.size());
        sub.labels.push_back(kValidationCutLabel);
      }
      sub.boundaries.push_back({p, s, cut_label});
    }
  return sub;
}

std::vector<int> validation_patches(const spline::MultiPatch& mp, const std::vector<bool>& eligible,
                                    const std::vector<double>& score, int max_patches) {
  const int n = static_cast<int>(mp.patches.size());
  int start = -1;
  for (int p = 0; p < n; ++p)
    if (eligible[p] && (start < 0 || score[p] < score[start])) start = p;
  if (start < 0) return {};
  if (max_patches <= 0 || max_patches >= n) {
    std::vector<int> all;
    for (int p = 0; p < n; ++p)
      if (eligible[p]) all.push_back(p);
    return all;
  }
  std::vector<std::set<int>> neighbours(n);
  for (const auto& itf : mp.interfaces) {
    neighbours[itf.patch_a].insert(itf.patch_b);
    neighbours[itf.patch_b].insert(itf.patch_a);
  }
  std::vector<int> chosen{start};
  std::set<int> seen{start};
  std::deque<int> queue{start};
  while (!queue.empty() && static_cast<int>(chosen.size()) < max_patches) {
    const int p = queue.front();
    queue.pop_front();
    for (int q : neighbours[p]) {
      if (static_cast<int>(chosen.size()) >= max_patches) break;
      if (!eligible[q] || seen.count(q)) continue;
      seen.insert(q);
      chosen.push_back(q);
      queue.push_back(q);
    }
  }
  std::sort(chosen.begin(), chosen.end());
  return chosen;
}

iga_check::PipelineValidation run_validation_stage(const spline::MultiPatch& mp,
                                                   const iga_check::CheckReport& check,
                                                   const CaseValidation& options) {
  StageTimer timer;
  iga_check::PipelineValidation v;
  v.degree = min_degree(mp);
  v.required_rate = v.degree + 0.5;
  v.model_patches = static_cast<int>(mp.patches.size());
  // Only certified patches: solve_elasticity refuses a Jacobian that changes sign.
  std::vector<bool> eligible(mp.patches.size(), false);
  std::vector<double> score(mp.patches.size(), 0.0);
  for (std::size_t p = 0; p < mp.patches.size(); ++p) {
    eligible[p] = p < check.patches.size() && check.patches[p].passed;
    score[p] = p < check.quality.patches.size() ? check.quality.patches[p].scaled_jacobian.min : 0.0;
  }
  v.patch_list = validation_patches(mp, eligible, score, options.patches);
  v.patches = static_cast<int>(v.patch_list.size());
  if (v.patch_list.empty()) {
    v.message = "no patch has a certified positive Jacobian";
  } else {
    iga_check::ManufacturedOptions mo;
    mo.coarse_refine = options.coarse_refine;
    mo.fine_refine = options.fine_refine;
    mo.solver = options.solver == "cholesky" ? iga_check::LinearSolver::Cholesky
                                             : iga_check::LinearSolver::ConjugateGradient;
    try {
      // Also for the whole model: collapsed sides then get the cut label.
      const spline::MultiPatch sub = validation_submodel(mp, v.patch_list);
      const iga_check::ManufacturedStudy st = iga_check::manufactured_study(sub, mo);
      v.ran = true;
      for (const auto& l : st.levels) {
        v.levels.push_back({l.refine, l.elements, l.unknowns, l.h, l.l2_error, l.l2_relative, l.energy_relative,
                            l.seconds});
        v.solver = l.solver;
      }
      v.l2_rate = st.l2_rate;
      v.energy_rate = st.energy_rate;
      v.met = v.l2_rate >= v.required_rate;
    } catch (const Error& e) {
      if (e.kind() == ErrorKind::Internal) throw;
      v.message = e.what();
    }
  }
  if (v.ran) {
    const auto &c = v.levels.front(), &f = v.levels.back();
    std::printf("validation %7.2f s  manufactured solution on %d of %d patches, degree %d, %s: refine %d/%d "
                "(%lld/%lld unknowns), L2 error %.3e/%.3e (relative %.2e/%.2e), L2 rate %.2f %s p + 0.5 = %.1f: "
                "%s; energy rate %.2f\n",
                timer.seconds(), v.patches, v.model_patches, v.degree, v.solver.c_str(), c.refine, f.refine,
                c.unknowns, f.unknowns, c.l2_error, f.l2_error, c.l2_relative, f.l2_relative, v.l2_rate,
                v.met ? ">=" : "<", v.required_rate, v.met ? "met" : "NOT MET", v.energy_rate);
  } else {
    std::printf("validation %7.2f s  NOT RUN: %s\n", timer.seconds(), v.message.c_str());
  }
  std::fflush(stdout);
  return v;
}

LoadCaseLabels load_case_labels(const spline::MultiPatch& mp, const CaseLoadCase& lc) {
  // Every selection in order, with the key that names it.
  struct Sel {
    const CaseSideSelection* where;
    std::string key;
  };
  std::vector<Sel> sels;
  for (std::size_t i = 0; i < lc.fix.size(); ++i)
    sels.push_back({&lc.fix[i].where, "load_case.fix[" + std::to_string(i) + "]"});
  for (std::size_t i = 0; i < lc.pressure.size(); ++i)
    sels.push_back({&lc.pressure[i].where, "load_case.pressure[" + std::to_string(i) + "]"});
  for (std::size_t i = 0; i < lc.traction.size(); ++i)
    sels.push_back({&lc.traction[i].where, "load_case.traction[" + std::to_string(i) + "]"});

  LoadCaseLabels out;
  out.model = mp;
  // Per boundary side: the boxed selections holding it. Sides of one label
  // with the same set share a derived label "LABEL[box i,j]".
  std::vector<std::vector<int>> holders(mp.boundaries.size());
  for (std::size_t s = 0; s < sels.size(); ++s) {
    const CaseSideSelection& w = *sels[s].where;
    const auto it = std::find(mp.labels.begin(), mp.labels.end(), w.label);
    const int label = it == mp.labels.end() ? -1 : static_cast<int>(it - mp.labels.begin());
    int sides = 0, in = 0;
    for (std::size_t b = 0; b < mp.boundaries.size(); ++b) {
      if (mp.boundaries[b].label != label) continue;
      ++sides;
      if (w.box && in_box(side_centre(mp.patches[mp.boundaries[b].patch], mp.boundaries[b].side), *w.box)) {
        holders[b].push_back(static_cast<int>(s));
        ++in;
      }
    }
    if (sides == 0) {
      std::string known;
      std::set<int> used;
      for (const auto& bs : mp.boundaries) used.insert(bs.label);
      for (int l : used) known += (known.empty() ? "" : ", ") + mp.labels[l];
      throw bad_input("'" + sels[s].key + ".label': no boundary side is labelled '" + w.label +
                      "' (boundary labels: " + known + ")");
    }
    if (w.box && in == 0)
      throw bad_input("'" + sels[s].key + ".box': none of the " + std::to_string(sides) + " sides labelled '" +
                      w.label + "' has its centre in the box");
  }
  std::map<std::pair<int, std::vector<int>>, int> derived;
  for (std::size_t b = 0; b < mp.boundaries.size(); ++b) {
    if (holders[b].empty()) continue;
    const int label = mp.boundaries[b].label;
    auto key = std::make_pair(label, holders[b]);
    auto it = derived.find(key);
    if (it == derived.end()) {
      std::string name = mp.labels[label] + "[box";
      for (std::size_t i = 0; i < holders[b].size(); ++i) name += (i ? "," : " ") + std::to_string(holders[b][i]);
      name += "]";
      it = derived.emplace(key, static_cast<int>(out.model.labels.size())).first;
      out.model.labels.push_back(name);
    }
    out.model.boundaries[b].label = it->second;
  }
  // The labels each selection stands for: every label derived from its own
  // with it among the holders (boxed), or its own and all derived (unboxed).
  std::vector<std::vector<std::string>> names(sels.size());
  for (std::size_t s = 0; s < sels.size(); ++s) {
    const CaseSideSelection& w = *sels[s].where;
    std::set<int> labels;
    for (std::size_t b = 0; b < mp.boundaries.size(); ++b) {
      if (mp.labels[mp.boundaries[b].label] != w.label) continue;
      const bool held = std::find(holders[b].begin(), holders[b].end(), static_cast<int>(s)) != holders[b].end();
      if (!w.box || held) labels.insert(out.model.boundaries[b].label);
    }
    for (int l : labels) names[s].push_back(out.model.labels[l]);
  }
  std::size_t k = 0;
  for (std::size_t i = 0; i < lc.fix.size(); ++i) out.fix.push_back(names[k++]);
  for (std::size_t i = 0; i < lc.pressure.size(); ++i) out.pressure.push_back(names[k++]);
  for (std::size_t i = 0; i < lc.traction.size(); ++i) out.traction.push_back(names[k++]);
  return out;
}

LoadCaseResult run_load_case_stage(const spline::MultiPatch& mp, const CaseLoadCase& lc, const std::string& dir) {
  StageTimer timer;
  const LoadCaseLabels lab = load_case_labels(mp, lc);
  iga_check::ElasticityProblem problem;
  for (std::size_t i = 0; i < lc.fix.size(); ++i)
    for (const auto& l : lab.fix[i]) problem.fixed.push_back({l, lc.fix[i].components});
  for (std::size_t i = 0; i < lc.pressure.size(); ++i)
    for (const auto& l : lab.pressure[i]) problem.pressures.push_back({l, lc.pressure[i].value});
  for (std::size_t i = 0; i < lc.traction.size(); ++i)
    for (const auto& l : lab.traction[i]) problem.tractions.push_back({l, lc.traction[i].value});
  problem.body_force = lc.body_force;
  iga_check::ElasticityOptions options;
  options.refine = lc.refine;
  options.solver =
      lc.solver == "cholesky" ? iga_check::LinearSolver::Cholesky : iga_check::LinearSolver::ConjugateGradient;
  const iga_check::ElasticitySolution sol = iga_check::solve_elasticity(lab.model, problem, options);
  LoadCaseResult r;
  r.path = (std::filesystem::path(dir) / "result.h5").string();
  exporter::write_hdf5_model(sol.model, r.path);
  r.unknowns = sol.report.unknowns;
  r.strain_energy = sol.report.strain_energy;
  r.max_displacement = sol.report.max_displacement;
  r.solver = sol.report.solver;
  r.seconds = timer.seconds();
  std::printf("load case  %7.2f s  %lld unknowns (%lld fixed), %s; strain energy %.6g, max displacement %.6g; "
              "result.h5\n",
              r.seconds, r.unknowns, sol.report.fixed_dofs, r.solver.c_str(), r.strain_energy, r.max_displacement);
  std::fflush(stdout);
  return r;
}

}  // namespace igaprep::cli
