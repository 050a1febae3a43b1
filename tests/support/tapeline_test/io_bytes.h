// Small inputs for the mesh reader tests: the unit tetrahedron and a writer of binary values in
// either byte order (to build binary PLY/STL files byte by byte).
#pragma once

#include <tapeline_test/io.h>

#include <cstddef>
#include <cstring>
#include <string>
#include <utility>

namespace tapeline_test {

/// The tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1), faces oriented outwards.
inline const Points kTetraPoints = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
inline const Faces kTetraFaces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

/// Appends the bytes of `value` to `out`, most significant first when `big_endian`.
template <class T>
void put(std::string& out, T value, bool big_endian) {
    char b[sizeof(T)];
    std::memcpy(b, &value, sizeof(T));
    if (big_endian) {
        for (std::size_t i = 0; i < sizeof(T) / 2; ++i) {
            std::swap(b[i], b[sizeof(T) - 1 - i]);
        }
    }
    out.append(b, sizeof(T));
}

}  // namespace tapeline_test
