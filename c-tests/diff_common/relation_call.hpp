// One per-element relation call of CHE or CHF through the C API, shared by the surface and
// volume differential tests.
#pragma once

#include <topomesh/topomesh.h>

#include <cstdint>
#include <vector>

namespace diffcall {

// Calls `f` on element `id` into `out` (first given `reserve` entries), growing it once on
// BUFFER_TOO_SMALL. On success `out` holds the answer; otherwise it is empty.
template <class Mesh>
topomesh_status call_relation(topomesh_status (*f)(const Mesh *, uint32_t, uint32_t *, size_t,
                                                   size_t *),
                              const Mesh *m, uint32_t id, std::vector<uint32_t> &out,
                              size_t reserve) {
  if (out.capacity() < reserve) out.reserve(reserve);
  out.resize(out.capacity());
  size_t len = 0;
  topomesh_status s = f(m, id, out.data(), out.size(), &len);
  if (s == TOPOMESH_STATUS_BUFFER_TOO_SMALL) {
    out.resize(len);
    s = f(m, id, out.data(), out.size(), &len);
  }
  out.resize(s == TOPOMESH_STATUS_OK ? len : 0);
  return s;
}

} // namespace diffcall
