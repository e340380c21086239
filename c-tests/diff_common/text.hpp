// Reading the text mesh files of the differential tests: the whole file, its non-empty
// lines without '#' comments, and numbers. Shared by the OFF reader (diff_surface) and the
// TetGen reader (diff_volume).
#pragma once

#include <charconv>
#include <cstdio>
#include <string>
#include <system_error>
#include <vector>

namespace difftext {

// The vertices of a mesh read from a file: the part that the triangle soup (diff_surface)
// and the tetrahedron soup (diff_volume) share.
struct Points {
  std::string name;              // the file's name, without its folder (or extension)
  size_t n_vertices = 0;
  std::vector<double> positions; // 3 per vertex
};

// `path` without its folder.
inline std::string file_name(const std::string &path) {
  const auto slash = path.find_last_of('/');
  return path.substr(slash == std::string::npos ? 0 : slash + 1);
}

// Reads the whole file at `path` into `text`; false when it cannot.
inline bool slurp(const std::string &path, std::string &text) {
  std::FILE *f = std::fopen(path.c_str(), "rb");
  if (!f) return false;
  std::fseek(f, 0, SEEK_END);
  long size = std::ftell(f);
  std::fseek(f, 0, SEEK_SET);
  text.resize(size > 0 ? size_t(size) : 0);
  size_t got = std::fread(text.data(), 1, text.size(), f);
  std::fclose(f);
  return got == text.size();
}

// Splits a text into non-empty lines without '#' comments and surrounding blanks.
struct Lines {
  const char *p, *end;
  // The next such line as [b, e); false at the end.
  bool next(const char *&b, const char *&e) {
    while (p < end) {
      const char *s = p;
      while (p < end && *p != '\n') ++p;
      const char *t = p;
      if (p < end) ++p;
      for (const char *q = s; q < t; ++q)
        if (*q == '#') { t = q; break; }
      while (s < t && (*s == ' ' || *s == '\t' || *s == '\r')) ++s;
      while (t > s && (t[-1] == ' ' || t[-1] == '\t' || t[-1] == '\r')) --t;
      if (s < t) { b = s; e = t; return true; }
    }
    return false;
  }
};

inline void skip_ws(const char *&b, const char *e) {
  while (b < e && (*b == ' ' || *b == '\t' || *b == '\r')) ++b;
}

// Parses the next number of [b, e) (after blanks, with an optional '+') into `out`.
template <class T> bool num(const char *&b, const char *e, T &out) {
  skip_ws(b, e);
  if (b < e && *b == '+') ++b;
  auto r = std::from_chars(b, e, out);
  if (r.ec != std::errc()) return false;
  b = r.ptr;
  return true;
}

} // namespace difftext
