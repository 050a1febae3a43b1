// gc_peer: one geometry-central geodesic run on a mesh file, for benchmarks/reproduce.sh --peers.
//
//   gc_peer MESH.obj --method M --source S [--target T] [--out DISTANCES.txt]
//
// M is one of
//   gc-mmp      exact polyhedral distance (GeodesicAlgorithmExact, the MMP algorithm)
//   gc-heat     heat method (HeatMethodDistanceSolver); pre_seconds is the solver's set-up
//   gc-fmm      fast marching (FMMDistance)
//   gc-flipout  FlipOut: a Dijkstra edge path from S to T shortened by edge flips (a path, not a
//               field: the length goes into the JSON line, no distances are written)
//   gc-pc-heat  point-cloud heat method (PointCloudHeatSolver) on the mesh's vertices taken as
//               a point cloud; pre_seconds is the first solve minus a second one (the solver
//               builds its local triangulation and factorisations on first use)
// The distances (one per vertex of the file, in file order, "inf" when unreachable) go to --out;
// one JSON line with the timings goes to stdout. Loading the file and building the mesh are not
// timed; everything geometry-central computes from the positions on is.
#include "geometrycentral/pointcloud/point_cloud.h"
#include "geometrycentral/pointcloud/point_cloud_heat_solver.h"
#include "geometrycentral/pointcloud/point_position_geometry.h"
#include "geometrycentral/surface/exact_geodesics.h"
#include "geometrycentral/surface/fast_marching_method.h"
#include "geometrycentral/surface/flip_geodesics.h"
#include "geometrycentral/surface/heat_method_distance.h"
#include "geometrycentral/surface/manifold_surface_mesh.h"
#include "geometrycentral/surface/surface_mesh_factories.h"
#include "geometrycentral/surface/vertex_position_geometry.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace geometrycentral;
using namespace geometrycentral::surface;

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

struct Obj {
    std::vector<Vector3> points;
    std::vector<std::vector<size_t>> faces;
};

// Vertices and faces of a Wavefront OBJ ("f a/b/c ..." and negative indices accepted).
Obj read_obj(const std::string& path) {
    std::ifstream in(path);
    if (!in) {
        throw std::runtime_error("cannot open " + path);
    }
    Obj obj;
    std::string line;
    size_t line_no = 0;
    while (std::getline(in, line)) {
        ++line_no;
        std::istringstream ls(line);
        std::string tag;
        ls >> tag;
        if (tag == "v") {
            double x, y, z;
            if (!(ls >> x >> y >> z)) {
                throw std::runtime_error(path + ":" + std::to_string(line_no) + ": bad vertex");
            }
            obj.points.push_back(Vector3{x, y, z});
        } else if (tag == "f") {
            std::vector<size_t> face;
            std::string tok;
            while (ls >> tok) {
                const long i = std::strtol(tok.c_str(), nullptr, 10);
                const long n = static_cast<long>(obj.points.size());
                const long k = i > 0 ? i - 1 : n + i;
                if (i == 0 || k < 0 || k >= n) {
                    throw std::runtime_error(path + ":" + std::to_string(line_no) +
                                             ": bad face index " + tok);
                }
                face.push_back(static_cast<size_t>(k));
            }
            if (face.size() < 3) {
                throw std::runtime_error(path + ":" + std::to_string(line_no) + ": face with " +
                                         std::to_string(face.size()) + " vertices");
            }
            obj.faces.push_back(face);
        }
    }
    if (obj.points.empty() || obj.faces.empty()) {
        throw std::runtime_error(path + ": no vertices or no faces");
    }
    return obj;
}

void write_distances(const std::string& path, const std::vector<double>& d) {
    std::FILE* f = std::fopen(path.c_str(), "w");
    if (!f) {
        throw std::runtime_error("cannot write " + path);
    }
    for (double x : d) {
        if (std::isfinite(x)) {
            std::fprintf(f, "%.17g\n", x);
        } else {
            std::fprintf(f, "inf\n");
        }
    }
    if (std::fclose(f) != 0) {
        throw std::runtime_error("cannot write " + path);
    }
}

std::string json_number(double x) {
    if (!std::isfinite(x)) {
        return "null";
    }
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", x);
    return buf;
}

int usage() {
    std::cerr << "usage: gc_peer MESH.obj --method gc-mmp|gc-heat|gc-fmm|gc-flipout|gc-pc-heat "
                 "--source S [--target T] [--out DISTANCES.txt]\n";
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    std::string mesh_path, method, out;
    long source = -1, target = -1;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) {
                throw std::invalid_argument(a + " needs a value");
            }
            return argv[++i];
        };
        try {
            if (a == "--method") {
                method = value();
            } else if (a == "--source") {
                source = std::stol(value());
            } else if (a == "--target") {
                target = std::stol(value());
            } else if (a == "--out") {
                out = value();
            } else if (!a.empty() && a[0] != '-' && mesh_path.empty()) {
                mesh_path = a;
            } else {
                std::cerr << "gc_peer: unknown argument " << a << "\n";
                return usage();
            }
        } catch (const std::exception& e) {
            std::cerr << "gc_peer: " << e.what() << "\n";
            return usage();
        }
    }
    if (mesh_path.empty() || method.empty() || source < 0) {
        return usage();
    }
    try {
        Obj obj = read_obj(mesh_path);
        const size_t nv = obj.points.size();
        if (static_cast<size_t>(source) >= nv ||
            (target >= 0 && static_cast<size_t>(target) >= nv)) {
            throw std::runtime_error("vertex index out of range (" + std::to_string(nv) +
                                     " vertices)");
        }
        double pre = 0, query = 0, length = NAN;
        std::vector<double> dist;
        std::string extra;
        if (method == "gc-pc-heat") {
            pointcloud::PointCloud cloud(nv);
            pointcloud::PointData<Vector3> pos(cloud);
            for (size_t i = 0; i < nv; ++i) {
                pos[i] = obj.points[i];
            }
            pointcloud::PointPositionGeometry geom(cloud, pos);
            const pointcloud::Point src = cloud.point(static_cast<size_t>(source));
            auto t0 = Clock::now();
            pointcloud::PointCloudHeatSolver solver(cloud, geom);
            pointcloud::PointData<double> d = solver.computeDistance(src);
            const double first = seconds_since(t0);
            t0 = Clock::now();
            pointcloud::PointData<double> again = solver.computeDistance(src);
            query = seconds_since(t0);
            pre = std::max(0.0, first - query);
            dist.resize(nv);
            for (size_t i = 0; i < nv; ++i) {
                dist[i] = d[i];
            }
        } else {
            std::unique_ptr<ManifoldSurfaceMesh> mesh;
            std::unique_ptr<VertexPositionGeometry> geom;
            std::tie(mesh, geom) = makeManifoldSurfaceMeshAndGeometry(obj.faces, obj.points);
            if (mesh->nVertices() != nv) {
                throw std::runtime_error("the mesh has " + std::to_string(mesh->nVertices()) +
                                         " vertices, the file " + std::to_string(nv));
            }
            const Vertex src = mesh->vertex(static_cast<size_t>(source));
            VertexData<double> d;
            if (method == "gc-mmp") {
                auto t0 = Clock::now();
                GeodesicAlgorithmExact mmp(*mesh, *geom);
                pre = seconds_since(t0);
                t0 = Clock::now();
                mmp.propagate(src);
                d = mmp.getDistanceFunction();
                query = seconds_since(t0);
            } else if (method == "gc-heat") {
                auto t0 = Clock::now();
                HeatMethodDistanceSolver solver(*geom);
                pre = seconds_since(t0);
                t0 = Clock::now();
                d = solver.computeDistance(src);
                query = seconds_since(t0);
            } else if (method == "gc-fmm") {
                auto t0 = Clock::now();
                d = FMMDistance(*geom, std::vector<std::pair<Vertex, double>>{{src, 0.0}});
                query = seconds_since(t0);
            } else if (method == "gc-flipout") {
                if (target < 0) {
                    throw std::runtime_error("gc-flipout needs --target");
                }
                const Vertex dst = mesh->vertex(static_cast<size_t>(target));
                auto t0 = Clock::now();
                std::unique_ptr<FlipEdgeNetwork> net =
                    FlipEdgeNetwork::constructFromDijkstraPath(*mesh, *geom, src, dst);
                if (!net) {
                    throw std::runtime_error("no edge path between the vertices");
                }
                pre = seconds_since(t0);
                const double initial = net->length();
                t0 = Clock::now();
                net->iterativeShorten();
                query = seconds_since(t0);
                length = net->length();
                extra = ",\"dijkstra_length\":" + json_number(initial) +
                        ",\"target\":" + std::to_string(target);
            } else {
                throw std::runtime_error("unknown method " + method);
            }
            if (method != "gc-flipout") {
                dist.resize(nv);
                for (size_t i = 0; i < nv; ++i) {
                    dist[i] = d[mesh->vertex(i)];
                }
            }
        }
        if (!out.empty() && !dist.empty()) {
            write_distances(out, dist);
        }
#ifdef GC_HAVE_SUITESPARSE
        const bool suitesparse = true;
#else
        const bool suitesparse = false;
#endif
        std::cout << "{\"method\":\"" << method << "\",\"vertices\":" << nv
                  << ",\"source\":" << source << ",\"pre_seconds\":" << json_number(pre)
                  << ",\"query_seconds\":" << json_number(query)
                  << ",\"length\":" << json_number(length) << extra
                  << ",\"suitesparse\":" << (suitesparse ? "true" : "false")
                  << ",\"compiler_flags\":\"" << GC_PEER_FLAGS << "\"}" << std::endl;
    } catch (const std::exception& e) {
        std::cerr << "gc_peer: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
