// The dressed body as binary glTF 2.0 (.glb), written with TinyGLTF (Debian's libtinygltf-dev):
// two meshes in one scene, the body (grey) and the garment coloured by stretch (COLOR_0: blue at
// no stretch, through green and yellow to red at 10 % and more), both with normals.
//
// glTF fixes the frame: metres, +Y up, +Z to the front. The body's canonical frame has exactly
// these axes, so positions are the canonical millimetres / 1000 (feet on y = 0): viewers and
// engines show body and garment upright and at scale whatever the input's unit was.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/vec3.h>
#include <tapeline/garment/quality.h>

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <ostream>
#include <string>
#include <vector>

namespace tapeline::garment {

namespace internal {

/// Stretch colour ramp: 1.0 blue, 1.033 green, 1.067 yellow, ≥ 1.1 red (compressed: blue).
inline std::array<float, 3> stretch_colour(double s) {
    const double t = std::clamp((s - 1.0) / 0.1, 0.0, 1.0);
    if (t < 1.0 / 3) {
        const double u = 3 * t;
        return {0.f, float(u), float(1 - u)};
    }
    if (t < 2.0 / 3) {
        const double u = 3 * t - 1;
        return {float(u), 1.f, 0.f};
    }
    const double u = 3 * t - 2;
    return {1.f, float(1 - u), 0.f};
}

/// Appends one mesh (positions in metres, per-vertex normals, optional colours) to `model`.
inline void add_gltf_mesh(tinygltf::Model& model, const std::string& name,
                          const std::vector<Vec3>& points_mm, const std::vector<Tri>& tris,
                          const std::vector<std::array<float, 3>>* colours, int material) {
    std::vector<float> pos, nrm(points_mm.size() * 3, 0.f), col;
    float lo[3] = {1e30f, 1e30f, 1e30f}, hi[3] = {-1e30f, -1e30f, -1e30f};
    for (const Vec3& p : points_mm) {
        for (int k = 0; k < 3; ++k) {
            const float v = float(p[k] / 1000.0);
            pos.push_back(v);
            lo[k] = std::min(lo[k], v);
            hi[k] = std::max(hi[k], v);
        }
    }
    for (const Tri& t : tris) {
        const Vec3 n = vec3::cross(vec3::sub(points_mm[t[1]], points_mm[t[0]]),
                                   vec3::sub(points_mm[t[2]], points_mm[t[0]]));
        for (std::uint32_t v : t) {
            for (int k = 0; k < 3; ++k) {
                nrm[3 * v + k] += float(n[k]);
            }
        }
    }
    for (std::size_t v = 0; v < points_mm.size(); ++v) {
        const float l = std::sqrt(nrm[3 * v] * nrm[3 * v] + nrm[3 * v + 1] * nrm[3 * v + 1] +
                                  nrm[3 * v + 2] * nrm[3 * v + 2]);
        for (int k = 0; k < 3; ++k) {
            nrm[3 * v + k] = l > 0 ? nrm[3 * v + k] / l : (k == 1 ? 1.f : 0.f);
        }
    }
    if (colours) {
        for (const auto& c : *colours) {
            col.insert(col.end(), c.begin(), c.end());
        }
    }
    std::vector<std::uint32_t> idx;
    for (const Tri& t : tris) {
        idx.insert(idx.end(), t.begin(), t.end());
    }
    tinygltf::Buffer& buffer = model.buffers[0];
    const auto add_view = [&](const void* data, std::size_t bytes, int target) {
        while (buffer.data.size() % 4 != 0) {
            buffer.data.push_back(0);
        }
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = buffer.data.size();
        view.byteLength = bytes;
        view.target = target;
        const auto* b = static_cast<const unsigned char*>(data);
        buffer.data.insert(buffer.data.end(), b, b + bytes);
        model.bufferViews.push_back(view);
        return int(model.bufferViews.size() - 1);
    };
    const auto add_accessor = [&](int view, int component, std::size_t count, int type) {
        tinygltf::Accessor a;
        a.bufferView = view;
        a.componentType = component;
        a.count = count;
        a.type = type;
        model.accessors.push_back(a);
        return int(model.accessors.size() - 1);
    };
    const std::size_t nv = points_mm.size();
    const int pa = add_accessor(add_view(pos.data(), pos.size() * 4, TINYGLTF_TARGET_ARRAY_BUFFER),
                                TINYGLTF_COMPONENT_TYPE_FLOAT, nv, TINYGLTF_TYPE_VEC3);
    model.accessors[std::size_t(pa)].minValues = {lo[0], lo[1], lo[2]};
    model.accessors[std::size_t(pa)].maxValues = {hi[0], hi[1], hi[2]};
    const int na = add_accessor(add_view(nrm.data(), nrm.size() * 4, TINYGLTF_TARGET_ARRAY_BUFFER),
                                TINYGLTF_COMPONENT_TYPE_FLOAT, nv, TINYGLTF_TYPE_VEC3);
    const int ia =
        add_accessor(add_view(idx.data(), idx.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                     TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, idx.size(), TINYGLTF_TYPE_SCALAR);
    tinygltf::Primitive prim;
    prim.attributes["POSITION"] = pa;
    prim.attributes["NORMAL"] = na;
    if (colours) {
        prim.attributes["COLOR_0"] =
            add_accessor(add_view(col.data(), col.size() * 4, TINYGLTF_TARGET_ARRAY_BUFFER),
                         TINYGLTF_COMPONENT_TYPE_FLOAT, nv, TINYGLTF_TYPE_VEC3);
    }
    prim.indices = ia;
    prim.material = material;
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    tinygltf::Mesh mesh;
    mesh.name = name;
    mesh.primitives.push_back(prim);
    model.meshes.push_back(mesh);
    tinygltf::Node node;
    node.name = name;
    node.mesh = int(model.meshes.size() - 1);
    model.nodes.push_back(node);
    model.scenes[0].nodes.push_back(int(model.nodes.size() - 1));
}

}  // namespace internal

/// Writes the body and the garment (canonical mm) as one binary glTF scene to `out`.
/// `triangle_stretch` (per garment triangle) colours the garment's vertices.
/// \throws InvalidInput when TinyGLTF fails to write.
inline void write_dressed_glb(std::ostream& out, const std::vector<Vec3>& body_points,
                              const std::vector<Tri>& body_tris, const GarmentMesh& garment,
                              const std::vector<double>& triangle_stretch) {
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = "Tapeline";
    model.buffers.resize(1);
    model.scenes.resize(1);
    model.defaultScene = 0;
    tinygltf::Material skin, cloth;
    skin.name = "body";
    skin.pbrMetallicRoughness.baseColorFactor = {0.78, 0.72, 0.68, 1.0};
    skin.pbrMetallicRoughness.metallicFactor = 0;
    cloth.name = "garment";
    cloth.pbrMetallicRoughness.baseColorFactor = {1, 1, 1, 1};
    cloth.pbrMetallicRoughness.metallicFactor = 0;
    cloth.doubleSided = true;
    model.materials = {skin, cloth};
    internal::add_gltf_mesh(model, "body", body_points, body_tris, nullptr, 0);
    std::vector<double> vs(garment.positions.size(), 1.0);
    for (std::size_t f = 0; f < garment.triangles.size() && f < triangle_stretch.size(); ++f) {
        for (std::uint32_t v : garment.triangles[f]) {
            vs[v] = std::max(vs[v], triangle_stretch[f]);
        }
    }
    std::vector<std::array<float, 3>> colours;
    for (double s : vs) {
        colours.push_back(internal::stretch_colour(s));
    }
    internal::add_gltf_mesh(model, "garment", garment.positions, garment.triangles, &colours, 1);
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, out, false, true)) {
        throw InvalidInput("glTF: TinyGLTF could not write the scene");
    }
}

}  // namespace tapeline::garment
