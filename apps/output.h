// Writing per-vertex results the way the tool promises: `.txt` one value per input vertex per
// line (input order), `.ply` a coloured mesh; always atomically.
#pragma once

#include "app_types.h"

#include <array>
#include <ostream>
#include <string>
#include <vector>

namespace tapeline::app {

/// `per_mesh_vertex` is indexed by mesh vertex, `per_input_vertex` by input-file vertex.
/// Writes one distance as the .txt outputs do: the number at the stream's precision, or "inf".
void write_distance(std::ostream& out, double d);

void write_distances(const std::string& path, const Mesh& mesh,
                     const std::vector<double>& per_mesh_vertex,
                     const std::vector<double>& per_input_vertex);

/// Lower-case extension of a path including the dot ("" if none).
std::string extension_of(const std::string& path);

}  // namespace tapeline::app
