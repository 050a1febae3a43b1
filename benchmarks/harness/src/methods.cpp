#include "app_types.h"

#include <tapeline/core/errors.h>

#include <cstdlib>

namespace tapeline::app {

const std::vector<std::string>& distance_methods() {
    static const std::vector<std::string> methods = {
        "exact-mmp",  "exact-cgal",        "heat",      "heat-idt", "dijkstra", "gcf-exact",
        "gcf-window", "gcf-window-thesis", "gcf-points"};
    return methods;
}

MethodName parse_method_name(const std::string& given, std::size_t window) {
    MethodName out{given, window, false, true};
    std::string text = given;
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

MethodResult run_distance_method(const std::string& name, const Mesh& mesh, const Sources& sources,
                                 std::size_t default_window, const PointsMethodOptions& points) {
    const MethodName parsed = parse_method_name(name, default_window);
    const std::string& method = parsed.base;
    const std::size_t window = parsed.window;
    if (method == "exact-mmp") {
        return run_exact_mmp(mesh, sources);
    }
    if (method == "exact-cgal") {
        return run_exact_cgal(mesh, sources);
    }
    if (method == "heat") {
        return run_heat(mesh, sources, false);
    }
    if (method == "heat-idt") {
        return run_heat(mesh, sources, true);
    }
    if (method == "dijkstra") {
        return run_dijkstra(mesh, sources);
    }
    if (method == "gcf-exact") {
        return run_gcf(mesh, sources, 0, false, parsed.on_faces, parsed.repair);
    }
    if (method == "gcf-window" || method == "gcf-window-thesis") {
        if (window == 0) {
            throw InvalidInput("--window must be at least 1 for " + method +
                               " (gcf-exact flows all)");
        }
        return run_gcf(mesh, sources, window, method == "gcf-window-thesis", parsed.on_faces,
                       parsed.repair);
    }
    if (method == "gcf-points") {
        return run_gcf_points(mesh, sources, window, points);
    }
    std::string known;
    for (const std::string& m : distance_methods()) {
        known += (known.empty() ? "" : ", ") + m;
    }
    throw InvalidInput("unknown method '" + name + "' (known: " + known + ")");
}

}  // namespace tapeline::app
