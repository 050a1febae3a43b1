// Running one measurement in a child process of its own: its peak memory is its own, a crash or a
// time-out is a status and not the end of the benchmark (DESIGN.md §7).
#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace tapeline::bench {

struct ChildOutcome {
    std::string status;  ///< ok, invalid_input, solver_failed, timeout, crash
    std::string message;
    nlohmann::json fields;          ///< what the child measured
    std::vector<double> distances;  ///< only when the child sent them
    std::size_t peak_rss_bytes = 0;
};

/// Fills the JSON fields a run measured and, optionally, distances to send back.
using IsolatedWork = std::function<void(nlohmann::json& fields, std::vector<double>& distances)>;

/// Runs `work` in a forked child, killed after `timeout_seconds` (0: never) and limited to
/// `memory_limit_gb` of address space (0: no limit; an allocation beyond it is a crash with the
/// message "out of memory"). The child's exceptions become statuses (InvalidInput and
/// TopologyError: invalid_input, SolverFailure: solver_failed, others: crash); a signal is a
/// crash. Throws std::runtime_error when no child can be started.
ChildOutcome run_isolated(const IsolatedWork& work, double timeout_seconds, double memory_limit_gb);

}  // namespace tapeline::bench
