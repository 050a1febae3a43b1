// `tapeline pattern import|list|show|validate|export`: sewing patterns in one model and one
// database (SQLite file, `--db`, default under the user's data directory).
#include "commands.h"

#include <tapeline/core/atomic_write.h>
#include <tapeline/core/errors.h>
#include <tapeline/core/progress.h>
#include <tapeline/pattern/database.h>
#include <tapeline/pattern/dxf.h>
#include <tapeline/pattern/io_detect.h>
#include <tapeline/pattern/io_freesewing.h>
#include <tapeline/pattern/io_garmentcode.h>
#include <tapeline/pattern/io_json.h>
#include <tapeline/pattern/png.h>
#include <tapeline/pattern/svg.h>
#include <tapeline/pattern/validate.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <sys/stat.h>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

namespace tapeline::app {

// Defined in pattern_mesh.cpp (CGAL 2D meshing compiles in its own translation unit).
/// Returns the line that says what was written (as `shown_as`).
std::string export_pattern_mesh(const pattern::Pattern& p, const std::string& path, double edge_mm,
                                const std::string& shown_as);

namespace tp = tapeline::pattern;

bool is_file(const std::string& path) {
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

namespace {

std::string db_path(const std::string& given) {
    return given.empty() ? tp::default_pattern_database_path() : given;
}

/// Says when a read-only open had to fall back to SQLite's `immutable` mode.
void note_read_only_open(const tp::PatternDatabase& database) {
    if (database.open_report().immutable) {
        std::cerr << "tapeline: note: " << database.path()
                  << ": opened immutable (its WAL index cannot be created beside it), so changes "
                     "other processes make meanwhile are not seen\n";
    }
}

void print_validation(const tp::ValidationReport& r, const std::string& what) {
    for (const auto& w : r.warnings) {
        std::cerr << "tapeline: warning: " << what << ": " << w.message << '\n';
    }
}

struct ImportArgs {
    std::vector<std::string> files;
    std::string format = "auto";
    std::string db;
    bool replace = false;
};

void run_import(const ImportArgs& a) {
    // Every file is read and validated before the database is touched.
    std::vector<tp::Pattern> patterns;
    Progress progress("pattern import: files read", a.files.size());
    for (const std::string& f : a.files) {
        tp::ImportReport report;
        tp::Pattern p = tp::read_pattern_file(f, a.format, &report);
        print_validation(tp::require_valid(p, {}, f), f);
        for (const std::string& n : report.notes) {
            std::cerr << "tapeline: note: " << f << ": " << n << '\n';
        }
        patterns.push_back(std::move(p));
        progress.advance();
    }
    tp::PatternDatabase database(db_path(a.db));
    if (!a.replace) {
        // Refuse before storing anything, so that a rejected batch leaves the database as it was.
        for (std::size_t i = 0; i < patterns.size(); ++i) {
            if (database.contains(patterns[i].name)) {
                throw InvalidInput(a.files[i] + ": a pattern named '" + patterns[i].name +
                                   "' is already in " + database.path() +
                                   " (use --replace to overwrite it)");
            }
        }
    }
    tp::StoreOptions options;
    options.replace = a.replace;
    const std::vector<tp::StoreReport> reports = database.store_all(patterns, options);
    for (std::size_t i = 0; i < patterns.size(); ++i) {
        const tp::StoreReport& r = reports[i];
        std::cout << (r.replaced ? "replaced " : "stored ") << patterns[i].name << " ("
                  << patterns[i].pieces.size() << " pieces, " << patterns[i].seams.size()
                  << " seams; geometry " << r.compression.stored_bytes << " bytes, "
                  << std::setprecision(3) << r.compression.ratio << "x smaller than JSON) from "
                  << a.files[i] << " in " << database.path() << '\n';
    }
}

struct ListArgs {
    std::string db;
    tp::PatternQuery query;
    std::string tags;
};

void run_list(const ListArgs& a) {
    const std::string path = db_path(a.db);
    if (!is_file(path)) {
        throw InvalidInput(path +
                           ": no pattern database (import one with `tapeline pattern import`)");
    }
    tp::DatabaseOptions options;
    options.read_only = true;
    options.create = false;
    tp::PatternDatabase database(path, options);
    note_read_only_open(database);
    tp::PatternQuery q = a.query;
    std::stringstream ss(a.tags);
    for (std::string t; std::getline(ss, t, ',');) {
        if (!t.empty()) {
            q.tags.push_back(t);
        }
    }
    const auto rows = database.search(q);
    for (const tp::PatternSummary& s : rows) {
        std::string tags;
        for (const std::string& t : s.tags) {
            tags += (tags.empty() ? "" : ",") + t;
        }
        std::cout << s.name << "\t" << s.garment_type << "\t" << s.size << "\t" << s.designer
                  << "\t" << s.pieces << " pieces\t" << s.seams << " seams\t" << tags << '\n';
    }
    std::cerr << rows.size() << " of " << database.count() << " patterns in " << path << '\n';
}

void run_show(const std::string& name, const std::string& db, const std::string& format) {
    const tp::Pattern p = load_pattern(name, db, format);
    const tp::ValidationReport r = tp::validate(p);
    std::cout << "pattern " << p.name << "\n  designer: " << p.designer
              << "\n  garment type: " << p.garment_type << "\n  size: " << p.size
              << "\n  units: " << p.units << "\n  pieces: " << p.pieces.size() << '\n';
    for (const tp::Piece& piece : p.pieces) {
        std::cout << "    " << piece.name << ": " << piece.outline.edges.size()
                  << " edges, perimeter " << std::fixed << std::setprecision(1)
                  << tp::length(piece.outline) << " mm, cut " << piece.cut_count
                  << (piece.fold ? ", on fold" : "") << '\n';
        std::cout.unsetf(std::ios::fixed);
        std::cout << std::setprecision(6);
    }
    std::cout << "  seams: " << p.seams.size() << " (largest length mismatch " << std::fixed
              << std::setprecision(3) << r.largest_seam_mismatch_mm << " mm)\n  validation: ";
    std::cout.unsetf(std::ios::fixed);
    std::cout << std::setprecision(6)
              << (r.ok() ? "ok" : std::to_string(r.errors.size()) + " errors") << ", "
              << r.warnings.size() << " warnings\n";
    for (const auto& e : r.errors) {
        std::cout << "    error: " << e.message << '\n';
    }
    for (const auto& w : r.warnings) {
        std::cout << "    warning: " << w.message << '\n';
    }
}

void run_validate(const std::string& file, const std::string& format) {
    tp::ImportReport report;
    const tp::Pattern p = tp::read_pattern_file(file, format, &report);
    const tp::ValidationReport r = tp::require_valid(p, {}, file);
    print_validation(r, file);
    std::cout << file << ": valid (" << p.pieces.size() << " pieces, " << p.seams.size()
              << " seams, " << r.warnings.size() << " warnings)\n";
}

struct ExportArgs {
    std::string name;
    std::string db;
    std::string format = "auto";
    std::string svg, png, dxf, json, mesh;
    double pixels_per_mm = 2;
    double edge_mm = 10;
};

void run_export(const ExportArgs& a) {
    if (a.svg.empty() && a.png.empty() && a.dxf.empty() && a.json.empty() && a.mesh.empty()) {
        throw InvalidInput("give at least one of --svg, --png, --dxf, --json, --mesh");
    }
    // Every output is checked before any is written, and all are renamed into place together.
    OutputFiles outputs({a.svg, a.png, a.dxf, a.json, a.mesh});
    const tp::Pattern p = load_pattern(a.name, a.db, a.format);
    tp::require_valid(p, {}, a.name);
    std::ostringstream said;
    if (!a.svg.empty()) {
        tp::write_svg(p, outputs.temporary(a.svg));
        said << "wrote " << a.svg << '\n';
    }
    if (!a.png.empty()) {
        tp::PngOptions options;
        options.pixels_per_mm = a.pixels_per_mm;
        const tp::PngReport r = tp::write_png(p, outputs.temporary(a.png), options);
        said << "wrote " << a.png << " (" << r.width_px << " x " << r.height_px << " px)\n";
    }
    if (!a.dxf.empty()) {
        const tp::DxfReport r = tp::write_dxf(p, outputs.temporary(a.dxf));
        said << "wrote " << a.dxf << " (DXF-AAMA, " << r.blocks << " piece blocks)\n";
    }
    if (!a.json.empty()) {
        tp::write_pattern_json(p, outputs.temporary(a.json));
        said << "wrote " << a.json << '\n';
    }
    if (!a.mesh.empty()) {
        said << export_pattern_mesh(p, outputs.temporary(a.mesh), a.edge_mm, a.mesh);
    }
    outputs.commit();
    std::cout << said.str();
}

}  // namespace

// NAME in the database, or a pattern file when NAME is an existing file.
tp::Pattern load_pattern(const std::string& name_or_file, const std::string& db,
                         const std::string& format) {
    if (is_file(name_or_file)) {
        return tp::read_pattern_file(name_or_file, format, nullptr);
    }
    tp::DatabaseOptions options;
    options.read_only = true;
    options.create = false;
    const std::string path = db_path(db);
    if (!is_file(path)) {
        throw InvalidInput(name_or_file + ": no such pattern file, and no pattern database at " +
                           path + " (import one with `tapeline pattern import`)");
    }
    tp::PatternDatabase database(path, options);
    note_read_only_open(database);
    return database.load(name_or_file);
}

void register_pattern_commands(CLI::App& app) {
    CLI::App* pat = app.add_subcommand("pattern", "Sewing patterns: import, database, export");
    pat->require_subcommand(1);
    const std::string db_help =
        "Pattern database (SQLite file; default " + tp::default_pattern_database_path() + ")";
    const std::vector<std::string> formats = {"auto", "freesewing", "garmentcode", "json"};

    auto im = std::make_shared<ImportArgs>();
    CLI::App* import = pat->add_subcommand("import", "Import pattern files into the database");
    import
        ->add_option("files", im->files,
                     "FreeSewing JSON, GarmentCode specification or tapeline "
                     "pattern JSON files")
        ->required();
    import->add_option("--format", im->format, "File format (default: recognised from the file)")
        ->check(CLI::IsMember(formats));
    import->add_option("--db", im->db, db_help);
    import->add_flag("--replace", im->replace, "Replace a stored pattern of the same name");
    import->callback([im] { run_import(*im);
});

auto li = std::make_shared<ListArgs>();
CLI::App* list = pat->add_subcommand("list", "List or search the patterns in the database");
list->add_option("--db", li->db, db_help);
list->add_option("--name", li->query.name, "Name contains (case-insensitive)");
list->add_option("--designer", li->query.designer, "Designer contains (case-insensitive)");
list->add_option("--type", li->query.garment_type, "Garment type (exact)");
list->add_option("--size", li->query.size, "Size (exact)");
list->add_option("--tags", li->tags, "Comma-separated tags that must all be present");
list->callback([li] { run_list(*li); });

auto sh = std::make_shared<std::array<std::string, 3>>();
CLI::App* show = pat->add_subcommand("show", "Describe a pattern (database name or file)");
show->add_option("name", (*sh)[0], "Pattern name in the database, or a pattern file")->required();
show->add_option("--db", (*sh)[1], db_help);
show->add_option("--format", (*sh)[2], "Format when NAME is a file")->check(CLI::IsMember(formats));
show->callback([sh] { run_show((*sh)[0], (*sh)[1], (*sh)[2]); });

auto va = std::make_shared<std::array<std::string, 2>>();
CLI::App* validate = pat->add_subcommand(
    "validate", "Check a pattern file: closed simple outlines, seams, finite numbers, units");
validate->add_option("file", (*va)[0], "Pattern file")->required();
validate->add_option("--format", (*va)[1], "File format (default: recognised)")
    ->check(CLI::IsMember(formats));
validate->callback([va] { run_validate((*va)[0], (*va)[1]); });

auto ex = std::make_shared<ExportArgs>();
CLI::App* exp = pat->add_subcommand("export",
                                    "Write a pattern as SVG, PNG, DXF-AAMA, JSON or "
                                    "a triangle mesh per piece");
exp->add_option("name", ex->name, "Pattern name in the database, or a pattern file")->required();
exp->add_option("--db", ex->db, db_help);
exp->add_option("--format", ex->format, "Format when NAME is a file")
    ->check(CLI::IsMember(formats));
exp->add_option("--svg", ex->svg, "SVG drawing");
exp->add_option("--png", ex->png, "PNG drawing");
exp->add_option("--pixels-per-mm", ex->pixels_per_mm, "PNG resolution")->capture_default_str();
exp->add_option("--dxf", ex->dxf, "DXF-AAMA / ASTM D6673 file");
exp->add_option("--json", ex->json, "Tapeline pattern JSON");
exp->add_option("--mesh", ex->mesh, "Triangle mesh of the pieces (.obj or .ply, 2D as UVs)");
exp->add_option("--edge-length", ex->edge_mm, "Target mesh edge length in mm")
    ->capture_default_str();
exp->callback([ex] { run_export(*ex); });
}  // namespace tapeline::app

}  // namespace tapeline::app
