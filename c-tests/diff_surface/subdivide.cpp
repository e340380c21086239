// subdivide IN.off OUT.off LEVELS: 1-to-4 midpoint subdivision of a triangle mesh, repeated.
// Vertex order: the input vertices, then one new vertex per edge in order of first use.
// Triangle order: the four children of input triangle t are 4t .. 4t+3 (corner children
// first, the middle one last), so locality follows the input. Used by fetch-meshes.sh to
// make the large benchmark meshes; standalone (no topomesh, no peers).
#include "off_reader.hpp"

#include <cstdio>
#include <cstdlib>
#include <unordered_map>

int main(int argc, char **argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: subdivide IN.off OUT.off LEVELS\n");
    return 2;
  }
  diffmesh::Soup s;
  std::string err;
  if (!diffmesh::read_off(argv[1], s, err)) {
    std::fprintf(stderr, "subdivide: %s\n", err.c_str());
    return 1;
  }
  int levels = std::atoi(argv[3]);
  std::vector<double> p = s.positions;
  std::vector<uint32_t> t = s.triangles;
  for (int l = 0; l < levels; ++l) {
    size_t nt = t.size() / 3;
    std::unordered_map<uint64_t, uint32_t> mid;
    mid.reserve(nt * 2);
    std::vector<uint32_t> out;
    out.reserve(t.size() * 4);
    auto midpoint = [&](uint32_t a, uint32_t b) {
      uint64_t key = a < b ? (uint64_t(a) << 32 | b) : (uint64_t(b) << 32 | a);
      auto [it, fresh] = mid.try_emplace(key, uint32_t(p.size() / 3));
      if (fresh)
        for (int k = 0; k < 3; ++k) p.push_back(0.5 * (p[3 * a + k] + p[3 * b + k]));
      return it->second;
    };
    for (size_t i = 0; i < nt; ++i) {
      uint32_t a = t[3 * i], b = t[3 * i + 1], c = t[3 * i + 2];
      uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      uint32_t kids[12] = {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca};
      out.insert(out.end(), kids, kids + 12);
    }
    t.swap(out);
  }
  FILE *f = std::fopen(argv[2], "w");
  if (!f) {
    std::perror(argv[2]);
    return 1;
  }
  static char buf[1 << 20];
  std::setvbuf(f, buf, _IOFBF, sizeof buf);
  std::fprintf(f, "OFF\n%zu %zu 0\n", p.size() / 3, t.size() / 3);
  for (size_t i = 0; i < p.size(); i += 3)
    std::fprintf(f, "%.9g %.9g %.9g\n", p[i], p[i + 1], p[i + 2]);
  for (size_t i = 0; i < t.size(); i += 3)
    std::fprintf(f, "3 %u %u %u\n", t[i], t[i + 1], t[i + 2]);
  if (std::fclose(f) != 0) {
    std::perror(argv[2]);
    return 1;
  }
  std::printf("subdivide: %s: %zu vertices, %zu triangles\n", argv[2], p.size() / 3,
              t.size() / 3);
  return 0;
}
