// Piece meshing (CGAL constrained Delaunay + refinement, through the tapeline_test facade): every
// triangle positive, mesh area = area of the sampled outline, boundary vertices on the curves and
// never split, edge lengths bounded, seam sides paired one to one, OBJ/PLY output.
#include <tapeline/pattern/io_freesewing.h>
#include <tapeline/pattern/io_garmentcode.h>
#include <tapeline/pattern/meshing_types.h>

#include <tapeline_test/pattern.h>
#include <tapeline_test/pattern_mesh.h>

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>

using namespace tapeline::pattern;

namespace {

std::vector<std::string> shared_pattern_files(const std::string& kind) {
    std::vector<std::string> out;
    for (const auto& f :
         tapeline_test::files_ending(tapeline_test::shared_patterns_dir() + "/" + kind, ".json")) {
        if (f.find("measurement_sets") == std::string::npos) {
            out.push_back(f);
        }
    }
    return out;
}

struct PieceCheck {
    double max_edge = 0, worst_area_rel = 0, worst_on_curve = 0;
};

/// The invariants of one piece mesh.
void check_piece(const Piece& piece, const PieceMesh& m, const MeshingOptions& o, PieceCheck& c) {
    SCOPED_TRACE(piece.name);
    const std::size_t nb = m.boundary_count;
    ASSERT_GE(nb, 3u);
    ASSERT_EQ(m.boundary_params.size(), nb);
    ASSERT_EQ(m.xyz.size(), m.uv.size());
    ASSERT_EQ(m.edge_vertices.size(), piece.outline.edges.size());
    // Boundary vertices are points of the outline curves, in order, segments ≤ target.
    std::vector<Point2> ring(m.uv.begin(), m.uv.begin() + long(nb));
    for (std::size_t i = 0; i < nb; ++i) {
        const BoundaryParam& bp = m.boundary_params[i];
        const Point2 on = point_at(piece.outline.edges[bp.edge].curve, bp.t);
        c.worst_on_curve = std::max(c.worst_on_curve, distance(on, m.uv[i]));
        EXPECT_LE(distance(on, m.uv[i]), 1e-9);
        EXPECT_LE(distance(ring[i], ring[(i + 1) % nb]), o.target_edge_mm + 1e-9);
    }
    for (std::size_t e = 0; e < piece.outline.edges.size(); ++e) {
        const auto& ids = m.edge_vertices[e];
        EXPECT_LE(distance(m.uv[ids.front()], start_point(piece.outline.edges[e])), 1e-9);
        EXPECT_LE(distance(m.uv[ids.back()], end_point(piece.outline.edges[e])), 1e-9);
    }
    // Triangles: positive area, sum = area of the boundary polygon; the edges used once are
    // exactly the boundary segments (no Steiner point on the outline).
    double area = 0;
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
    for (const auto& t : m.triangles) {
        const Point2 a = m.uv[t[0]], b = m.uv[t[1]], d = m.uv[t[2]];
        const double ar = 0.5 * cross(b - a, d - a);
        EXPECT_GT(ar, 0);
        area += ar;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t u = t[k], v = t[(k + 1) % 3];
            ++uses[{std::min(u, v), std::max(u, v)}];
            c.max_edge = std::max(c.max_edge, distance(m.uv[u], m.uv[v]));
        }
    }
    const double ring_area = std::abs(signed_area(ring));
    c.worst_area_rel = std::max(c.worst_area_rel, std::abs(area - ring_area) / ring_area);
    EXPECT_NEAR(area, ring_area, 1e-6 * ring_area);
    std::size_t boundary_edges = 0;
    for (const auto& [e, n] : uses) {
        EXPECT_LE(n, 2);
        if (n == 1) {
            ++boundary_edges;
            ASSERT_LT(e.second, nb) << "a boundary edge ends at an interior vertex";
            const std::size_t d = e.second - e.first;
            EXPECT_TRUE(d == 1 || d == nb - 1) << e.first << "-" << e.second;
        }
    }
    EXPECT_EQ(boundary_edges, nb);
    // Every vertex is used.
    std::vector<bool> used(m.uv.size(), false);
    for (const auto& t : m.triangles) {
        used[t[0]] = used[t[1]] = used[t[2]] = true;
    }
    EXPECT_EQ(std::count(used.begin(), used.end(), false), 0);
    // 3D rest positions: the placement, or z = 0.
    for (std::size_t i = 0; i < m.uv.size(); i += 97) {
        const std::array<double, 3> want = piece.placement
                                               ? placed_point(*piece.placement, m.uv[i])
                                               : std::array<double, 3>{m.uv[i].x, m.uv[i].y, 0};
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(m.xyz[i][k], want[k], 1e-9);
        }
    }
}

void check_seams(const Pattern& pat, const PatternMesh& mesh) {
    ASSERT_EQ(mesh.seams.size(), pat.seams.size());
    for (std::size_t s = 0; s < pat.seams.size(); ++s) {
        const Seam& seam = pat.seams[s];
        const SeamStitch& st = mesh.seams[s];
        SCOPED_TRACE(pat.name + " seam " + std::to_string(s));
        const PieceMesh& ma = mesh.pieces[st.piece_a];
        const PieceMesh& mb = mesh.pieces[st.piece_b];
        EXPECT_EQ(ma.piece, seam.a.piece);
        EXPECT_EQ(mb.piece, seam.b.piece);
        // Vertex counts on each side, counted from the edges.
        std::size_t na = 1, nb = 1;
        const std::size_t ea = pat.pieces[st.piece_a].outline.edges.size();
        const std::size_t eb = pat.pieces[st.piece_b].outline.edges.size();
        for (std::size_t k = 0; k < seam.a.count; ++k) {
            na += ma.edge_vertices[(seam.a.first_edge + k) % ea].size() - 1;
        }
        for (std::size_t k = 0; k < seam.b.count; ++k) {
            nb += mb.edge_vertices[(seam.b.first_edge + k) % eb].size() - 1;
        }
        EXPECT_EQ(na, nb);
        ASSERT_EQ(st.pairs.size(), na);
        // Ends: start of A with start of B (same) or with the end of B (opposite).
        const std::uint32_t a0 = ma.edge_vertices[seam.a.first_edge].front();
        const std::uint32_t b0 = mb.edge_vertices[seam.b.first_edge].front();
        const std::uint32_t b1 =
            mb.edge_vertices[(seam.b.first_edge + seam.b.count - 1) % eb].back();
        EXPECT_EQ(st.pairs.front().first, a0);
        EXPECT_EQ(st.pairs.front().second, seam.direction == SeamDirection::same ? b0 : b1);
        // Paired vertices sit at the same fraction of their side's length (uniform arc-length
        // sampling of equal counts): compare the chord-length fractions, which differ from
        // arc-length fractions by far less than one segment.
        auto fractions = [](const PieceMesh& m, const std::vector<std::uint32_t>& ids) {
            std::vector<double> f(1, 0.0);
            for (std::size_t k = 1; k < ids.size(); ++k) {
                f.push_back(f.back() + distance(m.uv[ids[k - 1]], m.uv[ids[k]]));
            }
            for (double& x : f) {
                x /= f.back();
            }
            return f;
        };
        std::vector<std::uint32_t> ia, ib;
        for (const auto& [a, b] : st.pairs) {
            ia.push_back(a);
            ib.push_back(b);
        }
        const std::vector<double> fa = fractions(ma, ia), fb = fractions(mb, ib);
        for (std::size_t k = 0; k < fa.size(); ++k) {
            // A side of several edges is sampled edge by edge (simon's FreeSewing seams), so a
            // pair may sit up to one segment apart; on one-edge sides it is within half.
            EXPECT_NEAR(fa[k], fb[k],
                        (seam.a.count > 1 || seam.b.count > 1 ? 1.0 : 0.5) / double(fa.size()));
        }
    }
}

}  // namespace

TEST(PatternMeshing, TwoPiecePattern) {
    const Pattern pat = tapeline_test::two_piece_pattern();
    MeshingOptions o;
    o.target_edge_mm = 10;
    MeshingReport rep;
    const PatternMesh mesh = tapeline_test::mesh_pattern(pat, o, &rep);
    ASSERT_EQ(mesh.pieces.size(), 2u);
    PieceCheck c;
    for (std::size_t i = 0; i < 2; ++i) {
        check_piece(pat.pieces[i], mesh.pieces[i], o, c);
    }
    check_seams(pat, mesh);
    EXPECT_EQ(rep.boundary_steiner_points, 0u);
    EXPECT_LE(rep.max_edge_mm, o.target_edge_mm * std::sqrt(2.0));
    EXPECT_GE(rep.min_angle_deg, 5.0);
    // The side seam (a 300 mm line on both pieces) gets 30 segments on both sides.
    EXPECT_EQ(mesh.seams[0].pairs.size(), 31u);
}

TEST(PatternMeshing, SeamSidesOfDifferentEdgeCountsAreBalanced) {
    // Side A is one 300 mm edge, side B two edges (100 + 200 mm, the second subdivided at 50 mm
    // by its curvature-free length alone): counts are equalised by adding segments to the side
    // with fewer.
    Pattern pat = tapeline_test::two_piece_pattern();
    Piece& back = pat.pieces[1];
    back.outline.edges[3] = {Line{{0, 300}, {0, 100}}, ""};
    back.outline.edges.push_back({Line{{0, 100}, {0, 0}}, ""});
    pat.seams[0].b = {"back", 3, 2};
    MeshingOptions o;
    o.target_edge_mm = 7;
    const PatternMesh mesh = tapeline_test::mesh_pattern(pat, o);
    check_seams(pat, mesh);
    PieceCheck c;
    check_piece(pat.pieces[1], mesh.pieces[1], o, c);
}

TEST(PatternMeshing, EverySharedPattern) {
    std::vector<std::string> files = shared_pattern_files("garmentcode");
    const std::vector<std::string> fs = shared_pattern_files("freesewing");
    files.insert(files.end(), fs.begin(), fs.end());
    if (files.empty()) {
        GTEST_SKIP() << tapeline_test::shared_patterns_dir() << " absent";
    }
    MeshingOptions o;
    o.target_edge_mm = 10;
    double worst_edge_ratio = 0;
    for (const std::string& f : files) {
        const bool gc = f.find("/garmentcode/") != std::string::npos;
        const Pattern pat = gc ? read_garmentcode(f) : read_freesewing(f);
        MeshingReport rep;
        const PatternMesh mesh = tapeline_test::mesh_pattern(pat, o, &rep);
        ASSERT_EQ(mesh.pieces.size(), pat.pieces.size());
        PieceCheck c;
        for (std::size_t i = 0; i < pat.pieces.size(); ++i) {
            check_piece(pat.pieces[i], mesh.pieces[i], o, c);
        }
        check_seams(pat, mesh);
        if (gc) {
            EXPECT_FALSE(pat.seams.empty());
        }
        EXPECT_EQ(rep.boundary_steiner_points, 0u);
        worst_edge_ratio = std::max(worst_edge_ratio, c.max_edge / o.target_edge_mm);
        std::printf(
            "  %-24s %2zu pieces %3zu seams %6zu vertices %6zu triangles; max edge %.2f "
            "mm (boundary %.2f), min angle %.1f°, area error %.1e, on-curve %.0e mm, "
            "%.0f ms\n",
            pat.name.c_str(), rep.pieces, mesh.seams.size(), rep.vertices, rep.triangles,
            rep.max_edge_mm, rep.max_boundary_edge_mm, rep.min_angle_deg, c.worst_area_rel,
            c.worst_on_curve, 1e3 * rep.seconds);
        EXPECT_LE(rep.max_edge_mm, o.target_edge_mm * std::sqrt(2.0)) << f;
    }
    std::printf("worst max edge / target: %.3f\n", worst_edge_ratio);
}

TEST(PatternMeshing, ObjAndPlyOutput) {
    const Pattern pat = tapeline_test::two_piece_pattern();
    const PatternMesh mesh = tapeline_test::mesh_pattern(pat);
    std::ostringstream obj;
    write_mesh_obj(mesh, obj);
    std::istringstream in(obj.str());
    std::string line;
    std::size_t v = 0, vt = 0, f = 0, o = 0;
    std::vector<std::array<double, 2>> uvs;
    std::vector<std::array<double, 3>> xyz;
    while (std::getline(in, line)) {
        std::istringstream ls(line);
        std::string tag;
        ls >> tag;
        if (tag == "v") {
            std::array<double, 3> p{};
            ls >> p[0] >> p[1] >> p[2];
            xyz.push_back(p);
            ++v;
        } else if (tag == "vt") {
            std::array<double, 2> p{};
            ls >> p[0] >> p[1];
            uvs.push_back(p);
            ++vt;
        } else if (tag == "f") {
            ++f;
        } else if (tag == "o") {
            ++o;
        }
    }
    const std::size_t nv = mesh.pieces[0].uv.size() + mesh.pieces[1].uv.size();
    const std::size_t nf = mesh.pieces[0].triangles.size() + mesh.pieces[1].triangles.size();
    EXPECT_EQ(v, nv);
    EXPECT_EQ(vt, nv);
    EXPECT_EQ(f, nf);
    EXPECT_EQ(o, 2u);
    // vt = 2D pattern coordinates; v = the 3D placement (front at z = 120 mm).
    EXPECT_NEAR(uvs[5][0], mesh.pieces[0].uv[5].x, 1e-6);
    EXPECT_NEAR(uvs[5][1], mesh.pieces[0].uv[5].y, 1e-6);
    const auto want = placed_point(*pat.pieces[0].placement, mesh.pieces[0].uv[5]);
    EXPECT_NEAR(xyz[5][2], want[2], 1e-6);
    EXPECT_NEAR(xyz[5][2], 120, 1e-6);

    std::ostringstream ply;
    write_mesh_ply(mesh, ply, 0.001);
    const std::string text = ply.str();
    EXPECT_NE(text.find("element vertex " + std::to_string(nv) + "\n"), std::string::npos);
    EXPECT_NE(text.find("element face " + std::to_string(nf) + "\n"), std::string::npos);
    EXPECT_NE(text.find("property double u\n"), std::string::npos);
    std::size_t lines = 0;
    for (char c : text.substr(text.find("end_header\n") + 11)) {
        lines += c == '\n';
    }
    EXPECT_EQ(lines, nv + nf);

    tapeline_test::TempDir dir;
    write_mesh(mesh, dir.file("m.obj"));
    write_mesh(mesh, dir.file("m.ply"));
    EXPECT_EQ(tapeline_test::slurp(dir.file("m.obj")), obj.str());
    try {
        write_mesh(mesh, dir.file("m.stl"));
        ADD_FAILURE();
    } catch (const tapeline::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("m.stl: unknown mesh format"), std::string::npos);
    }
}

TEST(PatternMeshing, BadInputIsRejected) {
    auto expect_invalid = [](const Pattern& p, const MeshingOptions& o, const std::string& part) {
        try {
            tapeline_test::mesh_pattern(p, o);
            ADD_FAILURE() << "expected an error mentioning " << part;
        } catch (const tapeline::InvalidInput& e) {
            EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
        }
    };
    const Pattern good = tapeline_test::two_piece_pattern();
    MeshingOptions o;
    o.target_edge_mm = 0;
    expect_invalid(good, o, "target edge length must be positive");
    o.target_edge_mm = 1e-5;
    expect_invalid(good, o, "points on the outlines");
    o = {};
    o.aspect_bound = 0.3;
    expect_invalid(good, o, "aspect bound");
    Pattern bow = good;  // a bow tie: the outline crosses itself
    bow.pieces[1].outline = tapeline_test::polygon({{0, 0}, {200, 300}, {200, 0}, {0, 300}});
    expect_invalid(bow, {}, "piece 'back': the outline sampled every 10");
    Pattern bad_seam = good;
    bad_seam.seams[0].b.piece = "sleeve";
    expect_invalid(bad_seam, {}, "names missing piece 'sleeve'");
    bad_seam = good;
    bad_seam.seams[0].b.first_edge = 7;
    expect_invalid(bad_seam, {}, "names edges 7");
}
