// The jobs of `tapeline batch`, one job's run and the results database (batch_jobs.h).
#include "batch_jobs.h"

#include "commands.h"

#include <tapeline/bench/dress_run.h>
#include <tapeline/bench/measure_run.h>
#include <tapeline/core/atomic_write.h>
#include <tapeline/core/errors.h>
#include <tapeline/core/mesh_io.h>
#include <tapeline/garment/fabric.h>
#include <tapeline/garment/garment_io.h>
#include <tapeline/garment/picture.h>
#include <tapeline/measurement/measurement_json.h>
#include <tapeline/pattern/io_json.h>
#include <tapeline/pattern/validate.h>
#include <tapeline/sizes/json_formats.h>
#include <tapeline/sizes/read_input.h>
#ifdef TAPELINE_HAVE_GRADING
#include <tapeline/bench/grade_run.h>
#include <tapeline/grading/output.h>
#endif

#include <glob.h>
#include <png.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace tapeline::app::batch {

namespace fs = std::filesystem;
namespace tm = tapeline::measurement;
namespace tg = tapeline::garment;
using Json = nlohmann::json;

namespace {

const std::vector<std::string> kSteps = {"measure", "grade", "dress"};
const std::set<std::string> kKeys = {"id",    "body",     "bodies",  "units",    "up",
                                     "front", "pose",     "pattern", "patterns", "db",
                                     "from",  "from_set", "fabric",  "steps",    "options"};
/// Options of a job and the JSON type each takes.
const std::map<std::string, Json::value_t> kOptionKeys = {
    {"resolution_mm", Json::value_t::number_float},
    {"gap_mm", Json::value_t::number_float},
    {"sdf_cell_mm", Json::value_t::number_float},
    {"sew_seconds", Json::value_t::number_float},
    {"settle_seconds", Json::value_t::number_float},
    {"substeps", Json::value_t::number_unsigned},
    {"threads", Json::value_t::number_unsigned},
    {"self_collision", Json::value_t::boolean},
    {"without", Json::value_t::array},
    {"seed", Json::value_t::number_unsigned},
    {"population", Json::value_t::number_unsigned},
    {"generations", Json::value_t::number_unsigned},
    {"relax", Json::value_t::boolean},
    {"relax_iterations", Json::value_t::number_unsigned}};

std::string names_of(const std::set<std::string>& s) {
    std::string out;
    for (const auto& x : s) {
        out += (out.empty() ? "" : ", ") + x;
    }
    return out;
}

bool type_fits(const Json& v, Json::value_t want) {
    switch (want) {
        case Json::value_t::number_float:
            return v.is_number() && std::isfinite(v.get<double>());
        case Json::value_t::number_unsigned:
            return v.is_number_unsigned() || (v.is_number_integer() && v.get<long long>() >= 0);
        case Json::value_t::boolean:
            return v.is_boolean();
        case Json::value_t::array:
            if (!v.is_array()) {
                return false;
            }
            for (const Json& e : v) {
                if (!e.is_string()) {
                    return false;
                }
            }
            return true;
        default:
            return false;
    }
}

std::string string_key(const Json& j, const char* key, const std::string& where) {
    if (!j.contains(key)) {
        return "";
    }
    if (!j[key].is_string() || j[key].get<std::string>().empty()) {
        throw InvalidInput(where + ": '" + key + "' must be a non-empty string");
    }
    return j[key].get<std::string>();
}

/// `p` relative to the manifest's folder unless absolute.
std::string resolved(const std::string& p, const fs::path& base) {
    if (p.empty() || fs::path(p).is_absolute()) {
        return p;
    }
    return (base / p).lexically_normal().string();
}

std::vector<std::string> glob_paths(const std::string& pattern, const std::string& where) {
    glob_t g{};
    const int rc = ::glob(pattern.c_str(), 0, nullptr, &g);
    std::vector<std::string> out;
    if (rc == 0) {
        for (std::size_t i = 0; i < g.gl_pathc; ++i) {
            out.emplace_back(g.gl_pathv[i]);
        }
    }
    globfree(&g);
    if (out.empty()) {
        throw InvalidInput(where + ": 'bodies' " + pattern + " matches no file");
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::string stem_of(const std::string& path) {
    std::string s = fs::path(path).stem().string();
    for (char& c : s) {
        const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                        (c >= '0' && c <= '9') || c == '.' || c == '-' || c == '_';
        c = ok ? c : '_';
    }
    return s.empty() ? "job" : s;
}

void write_text(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    out.flush();
    if (!out) {
        throw InvalidInput(path.string() + ": cannot be written");
    }
}

/// An RGBA image from a PNG file (libpng's simplified reader).
draw::RgbaImage read_png(const std::string& path) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&image, path.c_str())) {
        throw InvalidInput(path + ": not a readable PNG (" + image.message + ")");
    }
    image.format = PNG_FORMAT_RGBA;
    draw::RgbaImage img;
    img.width = image.width;
    img.height = image.height;
    img.rgba.resize(PNG_IMAGE_SIZE(image));
    if (!png_image_finish_read(&image, nullptr, img.rgba.data(), 0, nullptr)) {
        png_image_free(&image);
        throw InvalidInput(path + ": not a readable PNG (" + image.message + ")");
    }
    return img;
}

}  // namespace

std::string JobSpec::spec() const {
    Json j;
    j["body"] = body;
    j["units"] = units;
    j["up"] = up;
    j["front"] = front;
    j["pose"] = pose;
    j["pattern"] = pattern;
    j["db"] = db;
    j["from"] = from;
    j["from_set"] = from_set;
    j["fabric"] = fabric;
    j["steps"] = steps;
    j["options"] = options;
    return j.dump();
}

std::vector<JobSpec> read_manifest(const std::string& path) {
    std::ifstream in(path);
    if (!in) {
        throw InvalidInput(path + ": cannot open the job manifest");
    }
    const fs::path base = fs::absolute(path).parent_path();
    std::vector<JobSpec> jobs;
    std::map<std::string, int> used_ids;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        const std::string where = path + ":" + std::to_string(number);
        const auto first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#') {
            continue;
        }
        Json j;
        try {
            j = Json::parse(line);
        } catch (const Json::parse_error& e) {
            throw InvalidInput(where + ": not a JSON object (" + e.what() + ")");
        }
        if (!j.is_object()) {
            throw InvalidInput(where + ": not a JSON object");
        }
        for (auto it = j.begin(); it != j.end(); ++it) {
            if (!kKeys.count(it.key())) {
                throw InvalidInput(where + ": unknown key '" + it.key() +
                                   "' (known: " + names_of(kKeys) + ")");
            }
        }
        JobSpec t;
        t.units = string_key(j, "units", where);
        // Axes and pose as given, else the defaults of `tapeline measure`.
        const tm::BodyOptions defaults;
        t.up = j.contains("up") ? string_key(j, "up", where) : defaults.up.to_string();
        t.front = j.contains("front") ? string_key(j, "front", where) : defaults.front.to_string();
        t.pose = j.contains("pose") ? string_key(j, "pose", where) : tm::to_string(defaults.pose);
        (void)tm::parse_body_options("", t.units, t.up, t.front, t.pose, where + ": ");
        t.db = resolved(string_key(j, "db", where), base);
        t.from = resolved(string_key(j, "from", where), base);
        t.from_set = string_key(j, "from_set", where);
        t.fabric = string_key(j, "fabric", where);
        if (!t.fabric.empty() && t.fabric.size() > 5 &&
            t.fabric.compare(t.fabric.size() - 5, 5, ".json") == 0) {
            t.fabric = resolved(t.fabric, base);
        }
        if (!t.fabric.empty()) {
            (void)tg::fabric_from(t.fabric);  // an unknown fabric is refused before any work
        }
        t.steps = kSteps;
        if (j.contains("steps")) {
            if (!j["steps"].is_array() || j["steps"].empty()) {
                throw InvalidInput(where +
                                   ": 'steps' must be a non-empty list of measure, "
                                   "grade, dress");
            }
            t.steps.clear();
            for (const Json& s : j["steps"]) {
                if (!s.is_string() ||
                    std::find(kSteps.begin(), kSteps.end(), s.get<std::string>()) == kSteps.end()) {
                    throw InvalidInput(where + ": unknown step " + s.dump() +
                                       " (steps: measure, grade, dress)");
                }
                t.steps.push_back(s.get<std::string>());
            }
            std::vector<std::string> ordered;
            for (const std::string& s : kSteps) {
                if (std::count(t.steps.begin(), t.steps.end(), s)) {
                    ordered.push_back(s);
                }
            }
            t.steps = ordered;
        }
        const bool grade = std::count(t.steps.begin(), t.steps.end(), "grade") > 0;
        if (grade && t.from.empty()) {
            throw InvalidInput(where +
                               ": the grade step needs 'from', the measurement set the pattern "
                               "was drafted for (or \"steps\" without grade)");
        }
        if (!grade && !t.from.empty()) {
            throw InvalidInput(where +
                               ": 'from' is for the grade step, which this job does not run");
        }
        t.options = Json::object();
        if (j.contains("options")) {
            if (!j["options"].is_object()) {
                throw InvalidInput(where + ": 'options' must be an object");
            }
            for (auto it = j["options"].begin(); it != j["options"].end(); ++it) {
                const auto known = kOptionKeys.find(it.key());
                if (known == kOptionKeys.end()) {
                    std::set<std::string> names;
                    for (const auto& k : kOptionKeys) {
                        names.insert(k.first);
                    }
                    throw InvalidInput(where + ": unknown option '" + it.key() +
                                       "' (known: " + names_of(names) + ")");
                }
                if (!type_fits(it.value(), known->second)) {
                    throw InvalidInput(where + ": option '" + it.key() + "' has the wrong type (" +
                                       it.value().dump() + ")");
                }
            }
            t.options = j["options"];
        }
        std::vector<std::string> bodies, patterns;
        if (j.contains("bodies")) {
            bodies = glob_paths(resolved(string_key(j, "bodies", where), base), where);
        }
        if (j.contains("body")) {
            bodies.push_back(resolved(string_key(j, "body", where), base));
        }
        if (j.contains("patterns")) {
            if (!j["patterns"].is_array() || j["patterns"].empty()) {
                throw InvalidInput(where + ": 'patterns' must be a non-empty list");
            }
            for (const Json& p : j["patterns"]) {
                if (!p.is_string() || p.get<std::string>().empty()) {
                    throw InvalidInput(where + ": 'patterns' must list non-empty strings");
                }
                patterns.push_back(p.get<std::string>());
            }
        }
        if (j.contains("pattern")) {
            patterns.push_back(string_key(j, "pattern", where));
        }
        if (bodies.empty()) {
            throw InvalidInput(where + ": missing 'body' (or 'bodies')");
        }
        const bool needs_pattern = grade || std::count(t.steps.begin(), t.steps.end(), "dress") > 0;
        if (patterns.empty() && needs_pattern) {
            throw InvalidInput(where + ": missing 'pattern' (or 'patterns')");
        }
        if (patterns.empty()) {
            patterns.push_back("");
        }
        const std::string given_id = string_key(j, "id", where);
        if (!given_id.empty() && bodies.size() * patterns.size() > 1) {
            throw InvalidInput(where + ": 'id' names one job; this line has " +
                               std::to_string(bodies.size() * patterns.size()));
        }
        for (const std::string& b : bodies) {
            for (const std::string& p : patterns) {
                JobSpec job = t;
                job.body = b;
                // A pattern is a file when one exists there, else a name in the database.
                const std::string file = resolved(p, base);
                job.pattern = (!p.empty() && fs::exists(file)) ? file : p;
                std::string id = given_id.empty()
                                     ? stem_of(b) + (p.empty() ? "" : "__" + stem_of(p))
                                     : stem_of(given_id);
                const int n = ++used_ids[id];
                if (n > 1) {
                    id += "_" + std::to_string(n);
                }
                job.id = id;
                jobs.push_back(std::move(job));
            }
        }
    }
    if (jobs.empty()) {
        throw InvalidInput(path + ": no jobs in the manifest");
    }
    return jobs;
}

nlohmann::json run_job(const JobSpec& job, const std::string& dir) {
    using Clock = std::chrono::steady_clock;
    fs::create_directories(dir);
    const auto has = [&](const char* step) {
        return std::count(job.steps.begin(), job.steps.end(), step) > 0;
    };
    const Json& o = job.options;
    const tm::BodyOptions bo =
        tm::parse_body_options(job.body, job.units, job.up, job.front, job.pose);
    Json outcome = Json::object();
    const auto t0 = Clock::now();
    const auto loaded = read_triangle_mesh<bench::Mesh>(job.body);
    std::optional<sizes::MeasurementSet> measured;
    std::optional<bench::MeasureRun> run;  // its landmarks also place the pieces
    double measure_seconds = 0;
    if (has("measure") || has("grade")) {
        const auto t1 = Clock::now();
        run = bench::measure_mesh(loaded.mesh, bo);
        const auto t2 = Clock::now();
        measure_seconds = std::chrono::duration<double>(t2 - t1).count();
        const nlohmann::ordered_json j =
            bench::measure_json(*run, job.body, std::chrono::duration<double>(t1 - t0).count(),
                                std::chrono::duration<double>(t2 - t0).count());
        if (has("measure")) {
            write_text(fs::path(dir) / "measure.json", j.dump(1) + "\n");
        }
        Json values = Json::object();
        for (const auto& m : j["measurements"]) {
            values[m["name"].get<std::string>()] = m["value_mm"];
        }
        outcome["height_mm"] = j["frame"]["height_mm"];
        outcome["measurements"] = values;
        outcome["missing"] = j["missing"].size();
        outcome["warnings"] = j["warnings"].size();
        measured = sizes::parse_measurement_json(Json::parse(j.dump()), job.body);
    }
    if (!has("grade") && !has("dress")) {
        return outcome;
    }
    pattern::Pattern pat = load_pattern(job.pattern, job.db, "");
    pattern::require_valid(pat);
    const int threads = o.contains("threads") ? o["threads"].get<int>() : 0;
    if (has("grade")) {
#ifdef TAPELINE_HAVE_GRADING
        const sizes::MeasurementSet from = sizes::read_measurement_input(job.from, job.from_set);
        grading::GradingOptions go;
        go.threads = std::size_t(threads);
        if (o.contains("seed")) {
            go.seed = o["seed"].get<std::uint32_t>();
        }
        if (o.contains("population")) {
            go.population = o["population"].get<std::size_t>();
        }
        if (o.contains("generations")) {
            go.generations = o["generations"].get<std::size_t>();
        }
        grading::GradeResult g = bench::grade_as_tool(std::move(pat), from, *measured, go, true);
        std::ostringstream graded;
        pattern::write_pattern_json(g.pattern, graded);
        write_text(fs::path(dir) / "graded.json", graded.str());
        write_text(fs::path(dir) / "grade.json", grading::report_json(g.report).dump(1) + "\n");
        outcome["grade"] = {{"max_fit_error_mm", g.report.max_fit_error_mm},
                            {"max_seam_mismatch_mm", g.report.max_seam_mismatch_mm}};
        pat = std::move(g.pattern);
#else
        throw InvalidInput(
            "grade: this tapeline was built without Ceres or pagmo, so it cannot grade");
#endif
    }
    if (has("dress")) {
        tg::DressOptions d;
        d.drape.threads = threads;
        if (!job.fabric.empty()) {
            d.fabric = tg::fabric_from(job.fabric);
        }
        if (o.contains("resolution_mm")) {
            d.resolution_mm = o["resolution_mm"].get<double>();
        }
        if (o.contains("gap_mm")) {
            d.placement.gap_mm = o["gap_mm"].get<double>();
        }
        if (o.contains("sdf_cell_mm")) {
            d.sdf_cell_mm = o["sdf_cell_mm"].get<double>();
        }
        if (o.contains("sew_seconds")) {
            d.sewing.sew_seconds = o["sew_seconds"].get<double>();
        }
        if (o.contains("settle_seconds")) {
            bench::set_settle_seconds(d.sewing, o["settle_seconds"].get<double>());
        }
        if (o.contains("substeps")) {
            d.drape.substeps = o["substeps"].get<int>();
        }
        if (o.contains("self_collision")) {
            d.drape.self_collision = o["self_collision"].get<bool>();
        }
        if (o.contains("relax")) {
            d.relax = o["relax"].get<bool>();
        }
        if (o.contains("relax_iterations")) {
            d.relax_options.max_iterations = o["relax_iterations"].get<int>();
            d.relax_again_options.max_iterations = d.relax_options.max_iterations;
        }
        if (o.contains("without")) {
            d.without_pieces = o["without"].get<std::vector<std::string>>();
        }
        const std::string pattern_name = pat.name;
        const bench::DressRun r = run ? bench::dress_measured(std::move(*run), bo.name,
                                                              std::move(pat), d, measure_seconds)
                                      : bench::dress_mesh(loaded.mesh, bo, std::move(pat), d);
        const tm::BodyFrame frame = r.body.frame;
        std::ostringstream obj;
        tg::write_garment_obj(obj, r.garment,
                              [frame](const tg::Vec3& p) { return frame.to_input(p); });
        write_text(fs::path(dir) / "dressed.obj", obj.str());
        write_text(fs::path(dir) / "dress.json",
                   bench::dress_report_json(r, job.body, job.pattern, d).dump(1) + "\n");
        // The thumbnail of the contact sheet: front, side and back, small.
        const draw::RgbaImage thumb =
            tg::dressed_picture(r.body.points(), r.body.triangles(), r.garment, r.stretch,
                                r.seam_lines, job.id, 0.025, 4);
        draw::write_png((fs::path(dir) / "thumb.png").string(), thumb, 4);
        Json failed = Json::array();
        for (const tg::Gate& g : r.report.gates) {
            if (!g.passed) {
                failed.push_back(g.name);
            }
        }
        outcome["dress"] = {{"pattern", pattern_name},
                            {"passed", r.report.passed},
                            {"failed_gates", failed},
                            {"stretch_p95", r.report.quality.stretch_p95},
                            {"top_drop_mm", r.report.quality.top_drop_mm},
                            {"garment_vertices", r.report.garment_vertices}};
    }
    return outcome;
}

// --- results database -------------------------------------------------------------------------

ResultsDb::ResultsDb(const std::string& path, bool create) : path_(path) {
    const int flags = SQLITE_OPEN_READWRITE | (create ? SQLITE_OPEN_CREATE : 0);
    if (sqlite3_open_v2(path.c_str(), &db_, flags, nullptr) != SQLITE_OK) {
        const std::string msg = db_ ? sqlite3_errmsg(db_) : "out of memory";
        sqlite3_close(db_);
        db_ = nullptr;
        throw InvalidInput(path + ": cannot open the results database (" + msg + ")");
    }
    sqlite3_busy_timeout(db_, 10000);
    exec("PRAGMA journal_mode=WAL");
    exec("PRAGMA synchronous=NORMAL");
    exec(
        "CREATE TABLE IF NOT EXISTS jobs (idx INTEGER PRIMARY KEY, id TEXT UNIQUE NOT NULL, "
        "spec TEXT NOT NULL, status TEXT NOT NULL, attempts INTEGER NOT NULL DEFAULT 0, "
        "error TEXT NOT NULL DEFAULT '', host TEXT NOT NULL DEFAULT '', rank INTEGER NOT NULL "
        "DEFAULT -1, started REAL NOT NULL DEFAULT 0, finished REAL NOT NULL DEFAULT 0, "
        "seconds REAL NOT NULL DEFAULT 0, outcome TEXT NOT NULL DEFAULT '')");
}

ResultsDb::~ResultsDb() {
    sqlite3_close(db_);
}

void ResultsDb::exec(const std::string& sql) {
    char* err = nullptr;
    if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &err) != SQLITE_OK) {
        const std::string msg = err ? err : "unknown error";
        sqlite3_free(err);
        throw InvalidInput(path_ + ": " + msg);
    }
}

namespace {

/// A prepared statement, finalised at the end of its scope.
struct Statement {
    Statement(sqlite3* db, const std::string& sql, const std::string& path) : db(db) {
        if (sqlite3_prepare_v2(db, sql.c_str(), -1, &s, nullptr) != SQLITE_OK) {
            throw InvalidInput(path + ": " + sqlite3_errmsg(db));
        }
    }
    ~Statement() { sqlite3_finalize(s); }
    Statement& text(int i, const std::string& v) {
        sqlite3_bind_text(s, i, v.c_str(), int(v.size()), SQLITE_TRANSIENT);
        return *this;
    }
    Statement& integer(int i, long long v) {
        sqlite3_bind_int64(s, i, v);
        return *this;
    }
    Statement& real(int i, double v) {
        sqlite3_bind_double(s, i, v);
        return *this;
    }
    void run(const std::string& path) {
        if (sqlite3_step(s) != SQLITE_DONE) {
            throw InvalidInput(path + ": " + sqlite3_errmsg(db));
        }
    }
    sqlite3* db;
    sqlite3_stmt* s = nullptr;
};

std::string column_text(sqlite3_stmt* s, int i) {
    const auto* t = sqlite3_column_text(s, i);
    return t ? reinterpret_cast<const char*>(t) : "";
}

}  // namespace

std::vector<JobRow> ResultsDb::rows() {
    Statement st(db_,
                 "SELECT idx, id, spec, status, attempts, error, host, rank, started, finished, "
                 "seconds, outcome FROM jobs ORDER BY idx",
                 path_);
    std::vector<JobRow> out;
    int rc;
    while ((rc = sqlite3_step(st.s)) == SQLITE_ROW) {
        JobRow r;
        r.index = sqlite3_column_int(st.s, 0);
        r.id = column_text(st.s, 1);
        r.spec = column_text(st.s, 2);
        r.status = column_text(st.s, 3);
        r.attempts = sqlite3_column_int(st.s, 4);
        r.error = column_text(st.s, 5);
        r.host = column_text(st.s, 6);
        r.rank = sqlite3_column_int(st.s, 7);
        r.started = sqlite3_column_double(st.s, 8);
        r.finished = sqlite3_column_double(st.s, 9);
        r.seconds = sqlite3_column_double(st.s, 10);
        r.outcome = column_text(st.s, 11);
        out.push_back(std::move(r));
    }
    if (rc != SQLITE_DONE) {
        throw InvalidInput(path_ + ": " + sqlite3_errmsg(db_));
    }
    return out;
}

void ResultsDb::insert(const JobRow& row) {
    Statement(db_, "INSERT INTO jobs (idx, id, spec, status) VALUES (?, ?, ?, ?)", path_)
        .integer(1, row.index)
        .text(2, row.id)
        .text(3, row.spec)
        .text(4, row.status)
        .run(path_);
}

void ResultsDb::start(int index, const std::string& host, int rank) {
    Statement(db_,
              "UPDATE jobs SET status = 'running', attempts = attempts + 1, host = ?, rank = ?, "
              "started = ?, error = '' WHERE idx = ?",
              path_)
        .text(1, host)
        .integer(2, rank)
        .real(3, now_seconds())
        .integer(4, index)
        .run(path_);
}

void ResultsDb::finish(int index, bool done, const std::string& error, double seconds,
                       const std::string& outcome) {
    Statement(db_,
              "UPDATE jobs SET status = ?, error = ?, finished = ?, seconds = ?, outcome = ? "
              "WHERE idx = ?",
              path_)
        .text(1, done ? "done" : "failed")
        .text(2, error)
        .real(3, now_seconds())
        .real(4, seconds)
        .text(5, outcome)
        .integer(6, index)
        .run(path_);
}

void ResultsDb::set_status(int index, const std::string& status) {
    Statement(db_, "UPDATE jobs SET status = ? WHERE idx = ?", path_)
        .text(1, status)
        .integer(2, index)
        .run(path_);
}

double now_seconds() {
    return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch())
        .count();
}

std::string host_name() {
    char buf[256] = {0};
    if (gethostname(buf, sizeof buf - 1) != 0) {
        return "unknown";
    }
    return buf;
}

// --- summary ----------------------------------------------------------------------------------

void write_summary(const std::string& out_dir, const std::vector<JobRow>& rows,
                   const nlohmann::json& run) {
    // The measurements shown per body: the main girths and lengths, in this order.
    const std::vector<std::string> shown = {
        "bust_girth",  "underbust_girth", "waist_girth",         "hip_girth",         "neck_girth",
        "thigh_girth", "upper_arm_girth", "shoulder_width_back", "shoulder_to_wrist", "inseam"};
    Json jobs = Json::array();
    std::map<std::string, std::vector<std::string>> failures;
    std::map<std::string, int> counts;
    std::ostringstream md;
    md << "# Batch summary\n\n";
    std::ostringstream body_table, job_table;
    body_table << "| job | body | height mm";
    for (const auto& n : shown) {
        body_table << " | " << n;
    }
    body_table << " | missing | warnings |\n|---|---|---:";
    for (std::size_t i = 0; i < shown.size(); ++i) {
        body_table << "|---:";
    }
    body_table << "|---:|---:|\n";
    job_table << "| job | status | attempts | seconds | host / rank | drape | failed gates | p95 "
                 "stretch |\n|---|---|---:|---:|---|---|---|---:|\n";
    for (const JobRow& r : rows) {
        ++counts[r.status];
        Json outcome = r.outcome.empty() ? Json::object() : Json::parse(r.outcome);
        const Json spec = Json::parse(r.spec);
        jobs.push_back({{"id", r.id},
                        {"body", spec["body"]},
                        {"pattern", spec["pattern"]},
                        {"status", r.status},
                        {"attempts", r.attempts},
                        {"error", r.error},
                        {"host", r.host},
                        {"rank", r.rank},
                        {"seconds", r.seconds},
                        {"outcome", outcome}});
        if (r.status == "failed") {
            failures[r.error].push_back(r.id);
        }
        if (outcome.contains("measurements")) {
            char h[32];
            std::snprintf(h, sizeof h, "%.0f", outcome["height_mm"].get<double>());
            body_table << "| " << r.id << " | "
                       << fs::path(spec["body"].get<std::string>()).filename().string() << " | "
                       << h;
            for (const auto& n : shown) {
                const Json& m = outcome["measurements"];
                if (m.contains(n)) {
                    char v[32];
                    std::snprintf(v, sizeof v, "%.0f", m[n].get<double>());
                    body_table << " | " << v;
                } else {
                    body_table << " | —";
                }
            }
            body_table << " | " << outcome["missing"] << " | " << outcome["warnings"] << " |\n";
        }
        std::string drape = "—", gates = "", p95 = "—";
        if (outcome.contains("dress")) {
            const Json& d = outcome["dress"];
            drape = d["passed"].get<bool>() ? "passed" : "failed";
            for (const auto& g : d["failed_gates"]) {
                gates += (gates.empty() ? "" : ", ") + g.get<std::string>();
            }
            char v[32];
            std::snprintf(v, sizeof v, "%.3f", d["stretch_p95"].get<double>());
            p95 = v;
        }
        char secs[32];
        std::snprintf(secs, sizeof secs, "%.1f", r.seconds);
        job_table << "| " << r.id << " | " << r.status << " | " << r.attempts << " | " << secs
                  << " | " << (r.host.empty() ? "—" : r.host + " / " + std::to_string(r.rank))
                  << " | " << drape << " | " << gates << " | " << p95 << " |\n";
    }
    Json counts_json = Json::object();
    md << rows.size() << " jobs:";
    for (const auto& [status, n] : counts) {
        counts_json[status] = n;
        md << " " << n << " " << status << ";";
    }
    char line[200];
    std::snprintf(line, sizeof line,
                  "This run: %d rank(s), %d job(s) in %.1f s; the coordinator's bookkeeping "
                  "%.3f ms per job.",
                  run.value("ranks", 1), run.value("jobs_run", 0), run.value("wall_seconds", 0.0),
                  run.value("coordinator_ms_per_job", 0.0));
    md << "\n\n" << line << "\n";
    md << "\n## Measurements per body (mm)\n\n" << body_table.str();
    md << "\n## Jobs\n\n" << job_table.str();
    Json failures_json = Json::array();
    if (!failures.empty()) {
        md << "\n## Failures by reason\n\n| reason | jobs |\n|---|---|\n";
        for (const auto& [reason, ids] : failures) {
            failures_json.push_back({{"reason", reason}, {"jobs", ids}});
            std::string list;
            for (const auto& id : ids) {
                list += (list.empty() ? "" : ", ") + id;
            }
            md << "| " << reason << " | " << list << " |\n";
        }
    }
    // The contact sheet: every dressed job's thumbnail, in job order, four to a row.
    std::vector<draw::RgbaImage> thumbs;
    for (const JobRow& r : rows) {
        const fs::path t = fs::path(out_dir) / "jobs" / r.id / "thumb.png";
        if (r.status == "done" && fs::exists(t)) {
            thumbs.push_back(read_png(t.string()));
        }
    }
    if (!thumbs.empty()) {
        std::size_t w = 0, h = 0;
        for (const auto& t : thumbs) {
            w = std::max(w, t.width);
            h = std::max(h, t.height);
        }
        const std::size_t columns = std::min<std::size_t>(4, thumbs.size());
        const std::size_t rows_n = (thumbs.size() + columns - 1) / columns;
        draw::RgbaImage sheet = draw::RgbaImage::filled(columns * w, rows_n * h, 255);
        draw::Canvas canvas(sheet, 4);
        for (std::size_t i = 0; i < thumbs.size(); ++i) {
            canvas.paste(thumbs[i], long((i % columns) * w), long((i / columns) * h));
        }
        draw::write_png((fs::path(out_dir) / "contact_sheet.png").string(), sheet, 4);
        md << "\n![contact sheet](contact_sheet.png)\n";
    }
    Json summary = {
        {"counts", counts_json}, {"run", run}, {"jobs", jobs}, {"failures", failures_json}};
    OutputFiles outputs({(fs::path(out_dir) / "summary.json").string(),
                         (fs::path(out_dir) / "summary.md").string()});
    outputs.write((fs::path(out_dir) / "summary.json").string(),
                  [&](std::ostream& out) { out << summary.dump(1) << '\n'; });
    outputs.write((fs::path(out_dir) / "summary.md").string(),
                  [&](std::ostream& out) { out << md.str(); });
    outputs.commit();
}

}  // namespace tapeline::app::batch
