// `tapeline`: the command-line tool. Subcommand families are registered by their own translation
// units; every failure becomes one line on stderr and a non-zero exit (DESIGN.md §4).
#include "commands.h"

#include <tapeline/core/errors.h>
#include <tapeline/core/progress.h>

#include <tapeline_build_info.h>

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <new>
#include <string>

namespace {

/// CLI11 answers an unknown command word with "A subcommand is required"; name the word instead.
void check_command_words(CLI::App& app, int argc, char** argv) {
    CLI::App* level = &app;
    std::string path;
    for (int i = 1; i < argc; ++i) {
        const std::string word = argv[i];
        const auto subcommands = level->get_subcommands([](CLI::App*) { return true; });
        if (word.empty() || word[0] == '-' || subcommands.empty()) {
            return;
        }
        CLI::App* next = nullptr;
        std::string names;
        for (CLI::App* s : subcommands) {
            names += (names.empty() ? "" : ", ") + s->get_name();
            if (s->check_name(word)) {
                next = s;
            }
        }
        if (!next) {
            throw tapeline::InvalidInput("unknown command '" + path + word +
                                         "' (expected one of: " + names + ")");
        }
        level = next;
        path += word + " ";
    }
}

/// CLI11 reads "" as 0, "-1" as the largest unsigned value, "1e999" and "nan" as numbers: every
/// option value is checked for what its type needs before the command sees it (ASCII digits for
/// whole numbers, within 32 bits; a finite number for real values; no empty text), so a typo is a
/// one-line refusal naming the option instead of a run of hours or a silent default. Options whose
/// work grows with their value also have a range of their own.
std::string check_value(const std::string& type, const std::string& v) {
    if (v.empty()) {
        return "empty value";
    }
    if (type.find("INT") != std::string::npos) {
        const bool is_unsigned = type.find("UINT") != std::string::npos;
        const std::size_t first = (!is_unsigned && v[0] == '-') ? 1 : 0;
        bool digits = v.size() > first && v.size() - first <= 10;
        for (std::size_t i = first; i < v.size() && digits; ++i) {
            digits = v[i] >= '0' && v[i] <= '9';
        }
        const double limit = is_unsigned ? 4294967295.0 : 2147483647.0;
        if (!digits || std::stod(v.substr(first)) > limit) {
            return "'" + v + "' is not a whole number" +
                   (is_unsigned ? " from 0 to 4294967295" : " within +-2147483647");
        }
    } else if (type.find("FLOAT") != std::string::npos) {
        char* end = nullptr;
        const double x = std::strtod(v.c_str(), &end);
        if (end != v.c_str() + v.size() || !std::isfinite(x)) {
            return "'" + v + "' is not a finite number";
        }
    }
    return "";
}

void check_option_values(CLI::App& app) {
    for (CLI::Option* opt : app.get_options()) {
        if (opt->get_type_size_max() == 0) {
            continue;  // a flag
        }
        const std::string type = opt->get_type_name();
        opt->check(CLI::Validator([type](std::string& v) { return check_value(type, v); }, "",
                                  "value of its type"));
    }
    for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
        check_option_values(*sub);
    }
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "Tapeline: geodesics on triangle meshes and point sets for virtual clothing.\n"
        "Run `tapeline SUBCOMMAND --help` for the options of each command."};
    app.require_subcommand(1);
    app.set_help_all_flag("--help-all", "Show the help of every subcommand");
    app.set_version_flag("--version", std::string("tapeline ") + TAPELINE_VERSION + " (git " +
                                          TAPELINE_GIT_REVISION + ")");
    // Global: accepted before or after the subcommand.
    app.fallthrough();
    auto* quiet = app.add_flag_callback(
        "--quiet", [] { tapeline::set_progress_mode(tapeline::ProgressMode::never); },
        "No progress lines on stderr");
    auto* progress = app.add_flag_callback(
        "--progress", [] { tapeline::set_progress_mode(tapeline::ProgressMode::always); },
        "Progress lines on stderr even when it is not a terminal (a pipe, a log file)");
    quiet->excludes(progress);
    // One line per failure, like every other error of the tool.
    app.failure_message([](const CLI::App*, const CLI::Error& e) {
        return "tapeline: error: " + std::string(e.what()) + " (see --help)\n";
    });
    tapeline::app::register_mesh_commands(app);
    tapeline::app::register_geodesic_commands(app);
    tapeline::app::register_bench_commands(app);
    tapeline::app::register_pattern_commands(app);
    tapeline::app::register_grade_commands(app);
    tapeline::app::register_measure_commands(app);
    tapeline::app::register_dress_commands(app);
    tapeline::app::register_fabric_commands(app);
    tapeline::app::register_batch_commands(app);
    tapeline::app::register_wrinkles_commands(app);
    check_option_values(app);
    try {
        check_command_words(app, argc, argv);
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    } catch (const tapeline::InvalidInput& e) {
        std::cerr << "tapeline: error: " << e.what() << '\n';
        return 2;
    } catch (const tapeline::TopologyError& e) {
        std::cerr << "tapeline: error: " << e.what() << '\n';
        return 3;
    } catch (const tapeline::SolverFailure& e) {
        std::cerr << "tapeline: solver failure: " << e.what() << '\n';
        return 4;
    } catch (const std::bad_alloc&) {
        std::cerr << "tapeline: error: out of memory\n";
        return 5;
    } catch (const std::exception& e) {
        std::cerr << "tapeline: internal error: " << e.what() << '\n';
        return 1;
    }
    return 0;
}
