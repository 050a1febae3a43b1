// Shared body of the libFuzzer targets: run one reader on the input; a refusal is one of
// Tapeline's typed exceptions, anything else (another exception, a crash, a sanitizer report, a
// hang) is a finding.
#pragma once

#include <tapeline/core/errors.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

namespace tapeline_fuzz {

template <class Read>
int run(const std::uint8_t* data, std::size_t size, Read read) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        read(text);
    } catch (const tapeline::InvalidInput&) {
    } catch (const tapeline::TopologyError&) {
    } catch (const tapeline::SolverFailure&) {
    } catch (const std::exception& e) {
        std::fprintf(stderr, "untyped exception: %s\n", e.what());
        std::abort();
    }
    return 0;
}

}  // namespace tapeline_fuzz
