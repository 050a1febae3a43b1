// Types shared by the command-line tool's translation units: the meshes, inputs and named
// distance methods of the benchmark harness (<tapeline/bench/methods.h>), which `tapeline
// geodesic` and `tapeline bench` share.
#pragma once

#include <tapeline/bench/methods.h>

namespace tapeline::app {

using bench::InputMesh;
using bench::Mesh;
using bench::MethodResult;
using bench::MethodSettings;
using bench::Point;
using bench::Sources;
using bench::Vertex;

using bench::default_window;
using bench::distance_methods;
using bench::load_input_mesh_file;
using bench::make_input_surface;
using bench::mesh_points;
using bench::parse_method_name;
using bench::run_distance_method;

}  // namespace tapeline::app
