#include "app_types.h"

#include <tapeline/core/errors.h>

namespace tapeline::app {

const std::vector<std::string>& distance_methods() {
    static const std::vector<std::string> methods = {
        "exact-mmp", "exact-cgal", "heat", "heat-idt", "dijkstra", "gcf-exact", "gcf-window"};
    return methods;
}

MethodResult run_distance_method(const std::string& method, const Mesh& mesh,
                                 const Sources& sources, std::size_t window) {
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
        return run_gcf(mesh, sources, 0);
    }
    if (method == "gcf-window") {
        if (window == 0) {
            throw InvalidInput("--window must be at least 1 for gcf-window (gcf-exact flows all)");
        }
        return run_gcf(mesh, sources, window);
    }
    std::string known;
    for (const std::string& m : distance_methods()) {
        known += (known.empty() ? "" : ", ") + m;
    }
    throw InvalidInput("unknown method '" + method + "' (known: " + known + ")");
}

}  // namespace tapeline::app
