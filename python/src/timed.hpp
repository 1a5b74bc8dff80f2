#pragma once
// Wall-clock timing of a call, for the "seconds" attributes of the meshes.
#include <chrono>

namespace pqmesh::python {

// Calls f() and returns the seconds it took (steady clock).
template <class F>
double seconds_of(F&& f) {
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace pqmesh::python
