#include <vcg_ext/crease_fill.h>

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

namespace {

/// A hole's patch as FillAcrossCreases takes it, read from tests/data.
struct Patch {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 3>> triangles;
  std::vector<char> is_fill, free;
};

Patch ReadPatch(const std::string& path) {
  std::ifstream in(path);
  std::stringstream body;
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#') body << line << '\n';
  Patch p;
  size_t nv = 0, nt = 0;
  body >> nv >> nt;
  for (size_t i = 0; i < nv; ++i) {
    Eigen::Vector3d q;
    int free = 0;
    body >> q.x() >> q.y() >> q.z() >> free;
    p.points.push_back(q);
    p.free.push_back(char(free));
  }
  for (size_t t = 0; t < nt; ++t) {
    std::array<int, 3> f{};
    int fill = 0;
    body >> f[0] >> f[1] >> f[2] >> fill;
    p.triangles.push_back(f);
    p.is_fill.push_back(char(fill));
  }
  return p;
}

} // namespace

// A fake hole's patch on Nefertiti where the smooth faces beside the hole, fitted with
// quadrics, curve apart inside it: the projections from one face's surface onto the other's
// ran off to infinity, and the validation scored a fill of infinite coordinates (its distance
// grid then asked for memory without end). The crease fill declines instead.
TEST(CreaseFill, FacesWhoseExtensionsDoNotMeetGiveNoFill) {
  const Patch p = ReadPatch(CI_TEST_DATA "/nefertiti_crease_patch.txt");
  ASSERT_EQ(p.points.size(), 853u);
  ASSERT_EQ(p.triangles.size(), 1599u);
  const vcg_ext::CreaseFill fill =
      vcg_ext::FillAcrossCreases(p.points, p.triangles, p.is_fill, p.free, {});
  EXPECT_NE(fill.problem.find("do not meet"), std::string::npos) << fill.problem;
  for (const auto& q : fill.points) EXPECT_TRUE(q.allFinite());
}
