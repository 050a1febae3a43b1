// Typed exceptions for Tapeline (DESIGN.md §4).
//
// User input is checked in Release builds too; a rejection throws one of these with a message that
// says what was wrong and where (file and line, vertex, face or piece). Expected non-results (an
// unreachable vertex, no path) are values, never exceptions.
#pragma once

#include <stdexcept>
#include <string>

namespace tapeline {

/// Bad user input: unreadable or malformed file, NaN coordinate, unknown option value, ...
class InvalidInput : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

/// The input is well formed but its topology is not one the algorithm accepts
/// (non-manifold edge, not a triangle mesh, ...).
class TopologyError : public std::domain_error {
public:
    using std::domain_error::domain_error;
};

/// A numerical solver did not produce a usable answer (factorisation failed, NaN result, ...).
class SolverFailure : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace tapeline
