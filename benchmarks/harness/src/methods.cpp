// The method table: each named method builds its library Options once, and both the run and the
// logged options come from that one construction.
#include <tapeline/bench/methods.h>

#include <tapeline/core/errors.h>
#include <tapeline/geodesic/curvature_flow_json.h>
#include <tapeline/geodesic/exact_mmp_json.h>
#include <tapeline/geodesic/geodesic_json.h>
#include <tapeline/geodesic/point_cloud_json.h>

#include <cstdlib>

namespace tapeline::bench {

namespace {

geodesic::HeatOptions heat_options(const MethodName& m) {
    geodesic::HeatOptions o;
    o.intrinsic_delaunay = m.base == "heat-idt";
    return o;
}

geodesic::FastMarchingOptions fmm_options(const MethodName& m) {
    geodesic::FastMarchingOptions o;
    o.unfold_obtuse = m.base != "fmm-no-unfold";
    return o;
}

MethodResult run_fmm_entry(const Mesh& mesh, const Sources& src, const MethodName& m,
                           const MethodSettings&) {
    return internal::run_fmm(mesh, src, fmm_options(m));
}

nlohmann::json fmm_json(const MethodName& m, const MethodSettings&) {
    return nlohmann::json(fmm_options(m));
}

geodesic::CurvatureFlowDistanceOptions gcf_options(const MethodName& m) {
    const bool thesis = m.base == "gcf-window-thesis";
    geodesic::CurvatureFlowDistanceOptions o;
    o.window = m.base == "gcf-exact" ? 0 : m.window;
    o.anchor = thesis ? geodesic::WindowAnchor::prefix : geodesic::WindowAnchor::field;
    o.cut_locus_guard = !thesis;  // gcf-window-thesis: the thesis' rule as written
    o.smooth_length = !m.on_faces;
    if (!m.repair) {
        o.repair_tolerance = -1;
    }
    if (m.window_steps > 0) {
        o.window_max_iterations = m.window_steps;
    }
    return o;
}

geodesic::PointCloudDistanceOptions points_options(const MethodName& m, const MethodSettings& s) {
    geodesic::PointCloudDistanceOptions o = s.points;
    o.window = m.window;
    return o;
}

/// Keys of the benchmark lines' options from before the options were written whole; kept so that
/// tables and scripts over older lines read newer ones the same way.
void add_summary_keys(nlohmann::json& j, const MethodName& m, const MethodSettings& s) {
    if (m.base == "gcf-points") {
        j["cell"] = s.points.cell_size;
        j["noise"] = s.noise;
    } else {
        j["length"] = m.on_faces ? "faces" : "smooth";
    }
    if (m.on_faces) {
        j["repair"] = m.repair;
    }
}

struct MethodEntry {
    const char* name;
    MethodResult (*run)(const Mesh&, const Sources&, const MethodName&, const MethodSettings&);
    nlohmann::json (*options)(const MethodName&, const MethodSettings&);
};

nlohmann::json gcf_json(const MethodName& m, const MethodSettings& s) {
    nlohmann::json j = gcf_options(m);
    add_summary_keys(j, m, s);
    return j;
}

MethodResult run_gcf_entry(const Mesh& mesh, const Sources& sources, const MethodName& m,
                           const MethodSettings&) {
    if (m.base != "gcf-exact" && m.window == 0) {
        throw InvalidInput("--window must be at least 1 for " + m.base + " (gcf-exact flows all)");
    }
    return internal::run_gcf(mesh, sources, gcf_options(m));
}

const std::vector<MethodEntry>& method_table() {
    using geodesic::DijkstraOptions;
    using geodesic::ExactCgalOptions;
    using geodesic::ExactMmpOptions;
    static const std::vector<MethodEntry> table = {
        {"exact-mmp",
         [](const Mesh& mesh, const Sources& src, const MethodName&, const MethodSettings&) {
             return internal::run_exact_mmp(mesh, src);
         },
         [](const MethodName&, const MethodSettings&) {
             return nlohmann::json(ExactMmpOptions{});
         }},
        {"exact-cgal",
         [](const Mesh& mesh, const Sources& src, const MethodName&, const MethodSettings&) {
             return internal::run_exact_cgal(mesh, src);
         },
         [](const MethodName&, const MethodSettings&) {
             return nlohmann::json(ExactCgalOptions{});
         }},
        {"heat",
         [](const Mesh& mesh, const Sources& src, const MethodName& m, const MethodSettings&) {
             return internal::run_heat(mesh, src, heat_options(m));
         },
         [](const MethodName& m, const MethodSettings&) {
             return nlohmann::json(heat_options(m));
         }},
        {"heat-idt",
         [](const Mesh& mesh, const Sources& src, const MethodName& m, const MethodSettings&) {
             return internal::run_heat(mesh, src, heat_options(m));
         },
         [](const MethodName& m, const MethodSettings&) {
             return nlohmann::json(heat_options(m));
         }},
        {"dijkstra",
         [](const Mesh& mesh, const Sources& src, const MethodName&, const MethodSettings&) {
             return internal::run_dijkstra(mesh, src);
         },
         [](const MethodName&, const MethodSettings&) {
             return nlohmann::json(DijkstraOptions{});
         }},
        {"fmm", run_fmm_entry, fmm_json},
        {"fmm-no-unfold", run_fmm_entry, fmm_json},
        {"gcf-exact", run_gcf_entry, gcf_json},
        {"gcf-window", run_gcf_entry, gcf_json},
        {"gcf-window-thesis", run_gcf_entry, gcf_json},
        {"gcf-points",
         [](const Mesh& mesh, const Sources& src, const MethodName& m, const MethodSettings& s) {
             return internal::run_gcf_points(mesh, src, points_options(m, s), s.noise, s.seed);
         },
         [](const MethodName& m, const MethodSettings& s) {
             nlohmann::json j = points_options(m, s);
             add_summary_keys(j, m, s);
             return j;
         }},
    };
    return table;
}

std::string known_methods() {
    std::string known;
    for (const std::string& m : distance_methods()) {
        known += (known.empty() ? "" : ", ") + m;
    }
    return known;
}

const MethodEntry& entry_of(const std::string& option, const std::string& given,
                            const MethodName& parsed) {
    for (const MethodEntry& e : method_table()) {
        if (parsed.base == e.name) {
            return e;
        }
    }
    throw InvalidInput(option + "unknown method '" + given + "' (known: " + known_methods() + ")");
}

}  // namespace

geodesic::PointCloudProjection parse_projection(const std::string& text,
                                                const std::string& option) {
    for (auto p : {geodesic::PointCloudProjection::mls, geodesic::PointCloudProjection::plane}) {
        if (text == geodesic::to_string(p)) {
            return p;
        }
    }
    throw InvalidInput(option + " '" + text + "': expected mls or plane");
}

const std::vector<std::string>& distance_methods() {
    static const std::vector<std::string> methods = [] {
        std::vector<std::string> names;
        for (const MethodEntry& e : method_table()) {
            names.push_back(e.name);
        }
        return names;
    }();
    return methods;
}

MethodName parse_method_name(const std::string& given, std::size_t window) {
    MethodName out{given, window, false, true};
    std::string text = given;
    const std::size_t steps_at = text.rfind("/steps:");
    if (steps_at != std::string::npos) {
        const std::string n = text.substr(steps_at + 7);
        char* end = nullptr;
        const unsigned long long value = std::strtoull(n.c_str(), &end, 10);
        if (text.rfind("gcf-window", 0) != 0 || n.empty() || *end != '\0' || value == 0 ||
            value > 100000) {
            throw InvalidInput("bad method '" + given +
                               "': '/steps:N' (flow steps of one window, N from 1 to 100000) "
                               "goes last on gcf-window and gcf-window-thesis");
        }
        out.window_steps = static_cast<std::size_t>(value);
        text.resize(steps_at);
        out.base = text;
    }
    const std::string raw = "/raw";
    if (text.size() > raw.size() && text.compare(text.size() - raw.size(), raw.size(), raw) == 0) {
        text.resize(text.size() - raw.size());
        out.repair = false;
        out.base = text;
    }
    const std::string faces = "/faces";
    if (text.size() > faces.size() &&
        text.compare(text.size() - faces.size(), faces.size(), faces) == 0) {
        text.resize(text.size() - faces.size());
        if (text.rfind("gcf-", 0) != 0) {
            throw InvalidInput("bad method '" + given +
                               "': only the gcf-* distance methods take '/faces'");
        }
        out.on_faces = true;
        out.base = text;
    }
    if (!out.repair && !out.on_faces) {
        throw InvalidInput("bad method '" + given +
                           "': '/raw' (no repair pass) goes after '/faces' on a gcf-* method");
    }
    const std::size_t colon = text.find(':');
    if (colon == std::string::npos) {
        return out;
    }
    out.base = text.substr(0, colon);
    const std::string w = text.substr(colon + 1);
    char* end = nullptr;
    const unsigned long long value = std::strtoull(w.c_str(), &end, 10);
    const bool takes_window = out.base.rfind("gcf-window", 0) == 0 || out.base == "gcf-points";
    if (!takes_window || w.empty() || *end != '\0' || value == 0 || value > 100000) {
        throw InvalidInput("bad method '" + given +
                           "': only gcf-window, gcf-window-thesis and gcf-points take ':W' with W "
                           "a window of 1 to 100000 samples");
    }
    out.window = static_cast<std::size_t>(value);
    return out;
}

void check_method_name(const std::string& option, const std::string& method) {
    entry_of(option + ": ", method, parse_method_name(method));
}

MethodResult run_distance_method(const std::string& name, const Mesh& mesh, const Sources& sources,
                                 const MethodSettings& settings) {
    const MethodName parsed = parse_method_name(name, settings.window);
    return entry_of("", name, parsed).run(mesh, sources, parsed, settings);
}

nlohmann::json method_options_json(const std::string& name, const MethodSettings& settings) {
    const MethodName parsed = parse_method_name(name, settings.window);
    return entry_of("", name, parsed).options(parsed, settings);
}

}  // namespace tapeline::bench
