// Point-set reading (core/point_io.h) for the I/O tests; its PLY path goes through the mesh
// readers, so it is compiled here once.
#include <tapeline/core/point_io.h>
#include <tapeline_test/io.h>

namespace tapeline_test {

PointSetView read_points(const std::string& path) {
    const tapeline::PointSet s = tapeline::read_point_set(path);
    return {s.file, s.format, s.dimension, s.coordinates, s.normals};
}

}  // namespace tapeline_test
