// BEXT: an independent reader (tests/export/read_bext.py, written from the
// layout in docs/export-formats.md) rebuilds each element from a part file
// (C^T times its nodes) and the element reproduces our geometry at random
// points; the deck has one part per material and the labels' node sets.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <regex>
#include <set>
#include <sstream>

#include "igaprep/export/bext.h"
#include "igaprep/export/export_model.h"
#include "igaprep/spline/basis.h"
#include "igaprep/spline/bezier_extraction.h"
#include "igaprep/spline/curve_surface.h"
#include "igaprep/spline/evaluate.h"
#include "test_model.h"
#include "test_util.h"

namespace {
using namespace igaprep::test;
namespace spline = igaprep::spline;

// The rational Bezier element at t in [0,1]^3 from its Bernstein points (u fastest).
Eigen::Vector3d bezier_at(const nlohmann::json& e, const Eigen::Vector3d& t) {
  const int p[3] = {e["degrees"][0], e["degrees"][1], e["degrees"][2]};
  std::vector<double> B[3];
  for (int d = 0; d < 3; ++d) {
    B[d].resize(static_cast<std::size_t>(p[d] + 1));
    spline::bernstein_basis(p[d], t[d], B[d].data());
  }
  Eigen::Vector4d h = Eigen::Vector4d::Zero();
  for (int k = 0; k <= p[2]; ++k)
    for (int j = 0; j <= p[1]; ++j)
      for (int i = 0; i <= p[0]; ++i) {
        const int b = i + (p[0] + 1) * (j + (p[1] + 1) * k);
        const double w = e["weights"][b].get<double>() * B[0][i] * B[1][j] * B[2][k];
        for (int c = 0; c < 3; ++c) h[c] += w * e["points"][b][c].get<double>();
        h[3] += w;
      }
  return h.head<3>() / h[3];
}

TEST(Bext, EachPartFileReproducesItsPatchesAtRandomPoints) {
  const std::string dir = scratch_dir("bext");
  const spline::MultiPatch mp = make_test_model();
  igaprep::exporter::export_model(mp, dir + "/m", {igaprep::exporter::Format::Bext});
  const std::vector<std::string> paths = igaprep::exporter::bext_paths(dir + "/m", 2);
  ASSERT_EQ(paths.size(), 3u);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0.0, diagonal = 2.0 * std::sqrt(3.0);
  int elements = 0;
  for (int m = 0; m < 2; ++m) {
    const CommandResult r = run_python("read_bext.py", {paths[static_cast<std::size_t>(m) + 1]});
    ASSERT_EQ(r.status, 0) << r.output.substr(0, 2000);
    const nlohmann::json j = nlohmann::json::parse(r.output);
    EXPECT_EQ(j["pid"].get<int>(), m + 1);
    std::vector<int> patches;  // the material's patches in model order: element block b is patches[b]
    for (int p = 0; p < static_cast<int>(mp.patches.size()); ++p)
      if (mp.patches[static_cast<std::size_t>(p)].material == m) patches.push_back(p);
    std::set<int> nodes_used;
    for (const auto& e : j["elements"]) {
      const spline::Patch& patch = mp.patches[static_cast<std::size_t>(patches.at(e["block"].get<std::size_t>()))];
      const spline::PatchExtraction ex = spline::bezier_extraction(patch);
      const int index = e["index"], nu = ex.element_count(0), nv = ex.element_count(1);
      const int el[3] = {index % nu, (index / nu) % nv, index / (nu * nv)};
      for (int d = 0; d < 3; ++d) EXPECT_EQ(e["degrees"][d].get<int>(), patch.degrees[d]);
      for (const auto& n : e["nodes"]) nodes_used.insert(n.get<int>());
      for (int s = 0; s < 20; ++s) {
        const Eigen::Vector3d t(unit(rng), unit(rng), unit(rng));
        Eigen::Vector3d xi;
        for (int d = 0; d < 3; ++d) {
          const auto& breaks = ex.dirs[static_cast<std::size_t>(d)].breaks;
          xi[d] = breaks[static_cast<std::size_t>(el[d])] + t[d] * (breaks[static_cast<std::size_t>(el[d]) + 1] - breaks[static_cast<std::size_t>(el[d])]);
        }
        worst = std::max(worst, (bezier_at(e, t) - spline::evaluate_point(patch, xi)).norm());
      }
      ++elements;
    }
    // The part's control points, each used, interface points once per part.
    EXPECT_EQ(static_cast<int>(nodes_used.size()), j["nodes"].get<int>());
    EXPECT_EQ(*nodes_used.rbegin(), j["nodes"].get<int>());
    // Each distinct coefficient vector once (per group of patches with the
    // same degrees), not one per element and function: between the count of
    // distinct rows and the count of rows distinct beyond 1e-10.
    std::map<std::array<int, 3>, std::set<std::vector<double>>> exact;
    std::map<std::array<int, 3>, std::set<std::vector<long long>>> beyond;
    long long per_element = 0;
    for (const int p : patches) {
      const spline::Patch& patch = mp.patches[static_cast<std::size_t>(p)];
      const spline::PatchExtraction ex = spline::bezier_extraction(patch);
      for (int e = 0; e < ex.element_count(); ++e) {
        const Eigen::MatrixXd C = spline::element_extraction_operator(
            ex, e % ex.element_count(0), (e / ex.element_count(0)) % ex.element_count(1),
            e / (ex.element_count(0) * ex.element_count(1)));
        for (Eigen::Index r = 0; r < C.rows(); ++r, ++per_element) {
          std::vector<double> row;
          std::vector<long long> coarse;
          for (Eigen::Index c = 0; c < C.cols(); ++c) {
            row.push_back(C(r, c));
            coarse.push_back(std::llround(C(r, c) * 1e10));
          }
          exact[patch.degrees].insert(row);
          beyond[patch.degrees].insert(coarse);
        }
      }
    }
    long long n_exact = 0, n_beyond = 0;
    for (const auto& [d, rows] : exact) n_exact += static_cast<long long>(rows.size());
    for (const auto& [d, rows] : beyond) n_beyond += static_cast<long long>(rows.size());
    EXPECT_LE(j["vectors"].get<long long>(), n_exact);
    EXPECT_GE(j["vectors"].get<long long>(), n_beyond);
    EXPECT_LT(j["vectors"].get<long long>(), per_element);
  }
  int total = 0;
  for (const auto& p : mp.patches) total += spline::bezier_extraction(p).element_count();
  EXPECT_EQ(elements, total);
  EXPECT_LT(worst, 1e-12 * diagonal);
  std::filesystem::remove_all(dir);
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(Bext, DeckHasOnePartPerMaterialAndTheLabelsNodeSets) {
  const std::string dir = scratch_dir("bext_deck");
  const spline::MultiPatch mp = make_test_model();
  igaprep::exporter::export_model(mp, dir + "/m", {igaprep::exporter::Format::Bext});
  const std::string deck = read_text(dir + "/m.k");
  auto count = [&](const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = deck.find(what); at != std::string::npos; at = deck.find(what, at + 1)) ++n;
    return n;
  };
  EXPECT_EQ(deck.rfind("*KEYWORD\n", 0), 0u);
  EXPECT_EQ(count("*PART\n"), 2u);
  EXPECT_EQ(count("*MAT_ELASTIC\n"), 2u);
  EXPECT_EQ(count("*SECTION_IGA_SOLID\n"), 2u);
  EXPECT_EQ(count("*IGA_INCLUDE_BEZIER\nm_part1.bext\n"), 1u);
  EXPECT_EQ(count("*IGA_INCLUDE_BEZIER\nm_part2.bext\n"), 1u);
  EXPECT_NE(deck.find("\nsteel\n"), std::string::npos);
  EXPECT_NE(deck.find("\nrubber\n"), std::string::npos);
  // Young's modulus of each material in its *MAT_ELASTIC card (fields of 10).
  for (std::size_t m = 0; m < 2; ++m) {
    char card[64];
    std::snprintf(card, sizeof card, "%10d%10.7g%10.7g%10.7g", static_cast<int>(m) + 1, 1.0,
                  mp.materials[m].young_modulus, mp.materials[m].poisson_ratio);
    EXPECT_NE(deck.find(card), std::string::npos) << card << "\n" << deck.substr(0, 1500);
  }
  // A node set per label and part that has it; its ids are the part's
  // control points on those sides.
  const std::regex set_re(R"(\*SET_NODE_LIST_TITLE\n(\S+) \(part (\d),[^\n]*\n\$#     sid\n +\d+\n((?: +\d+)+\n(?:(?: +\d+)+\n)*))");
  int sets = 0;
  for (std::sregex_iterator it(deck.begin(), deck.end(), set_re), end; it != end; ++it) {
    const std::string label = (*it)[1];
    const int pid = std::stoi((*it)[2]);
    std::set<long long> ids;
    std::stringstream s((*it)[3].str());
    for (long long id; s >> id;) ids.insert(id);
    // Expected: the number of distinct control points of the part's sides with that label.
    std::set<std::array<long long, 3>> points;
    for (const auto& b : mp.boundaries) {
      const spline::Patch& p = mp.patches[static_cast<std::size_t>(b.patch)];
      if (mp.labels[static_cast<std::size_t>(b.label)] != label || p.material != pid - 1) continue;
      for (int l : spline::side_control_points(p, b.side))
        points.insert({std::llround(p.control_points(l, 0) * 1e9), std::llround(p.control_points(l, 1) * 1e9),
                       std::llround(p.control_points(l, 2) * 1e9)});
    }
    EXPECT_EQ(ids.size(), points.size()) << label << " part " << pid;
    ++sets;
  }
  EXPECT_EQ(sets, 4);  // T1_outer and base, in each of the two parts
  EXPECT_EQ(deck.substr(deck.size() - 5), "*END\n");
  std::filesystem::remove_all(dir);
}

}  // namespace
