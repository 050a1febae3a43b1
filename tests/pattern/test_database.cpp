// The pattern database: compressed round trip of every shared pattern (edges within 0.01 mm at
// equal curve parameters, metadata equal), search by each field, the v1 → v2 migration, refusal of
// damaged, foreign and future files, a writer killed mid-loop (SIGKILL) and readers running beside
// a writer (WAL).
#include <tapeline/pattern/compression.h>
#include <tapeline/pattern/database.h>
#include <tapeline/pattern/io_freesewing.h>
#include <tapeline/pattern/io_garmentcode.h>
#include <tapeline/pattern/io_json.h>

#include <tapeline_test/pattern.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <random>
#include <thread>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace tapeline::pattern;
using tapeline_test::TempDir;
using tapeline_test::two_piece_pattern;

namespace {

/// The in-repo patterns (always present) plus the shared ones (when the shared data is there).
std::vector<Pattern> test_patterns() {
    std::vector<Pattern> out;
    out.push_back(two_piece_pattern());
    out.push_back(
        read_freesewing(std::string(TAPELINE_DATA_DIR) + "/patterns/aaron_cisFemaleAdult36.json"));
    out.back().name += " (repo)";
    out.push_back(read_garmentcode(std::string(TAPELINE_DATA_DIR) +
                                   "/patterns/shirt_mean_specification.json"));
    out.back().name += " (repo)";
    for (const std::string& f : tapeline_test::shared_pattern_files()) {
        out.push_back(tapeline_test::load_shared_pattern(f));
    }
    return out;
}

void expect_invalid(const std::function<void()>& f, std::initializer_list<std::string> parts) {
    try {
        f();
        ADD_FAILURE() << "no exception; expected one mentioning " << *parts.begin();
    } catch (const tapeline::InvalidInput& e) {
        for (const std::string& p : parts) {
            EXPECT_NE(std::string(e.what()).find(p), std::string::npos)
                << "message '" << e.what() << "' lacks '" << p << "'";
        }
    }
}

/// Everything but the geometry: equal field by field.
void expect_same_metadata(const Pattern& a, const Pattern& b) {
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.designer, b.designer);
    EXPECT_EQ(a.garment_type, b.garment_type);
    EXPECT_EQ(a.size, b.size);
    EXPECT_EQ(a.tags, b.tags);
    EXPECT_EQ(a.source, b.source);
    EXPECT_EQ(a.units, b.units);
    EXPECT_EQ(a.measurements_used, b.measurements_used);
    ASSERT_EQ(a.pieces.size(), b.pieces.size());
    for (std::size_t i = 0; i < a.pieces.size(); ++i) {
        const Piece &pa = a.pieces[i], &pb = b.pieces[i];
        EXPECT_EQ(pa.name, pb.name);
        EXPECT_EQ(pa.label, pb.label);
        EXPECT_EQ(pa.cut_count, pb.cut_count);
        EXPECT_EQ(pa.mirrored, pb.mirrored);
        EXPECT_EQ(pa.notches.size(), pb.notches.size());
        EXPECT_EQ(pa.points.size(), pb.points.size());
        EXPECT_EQ(pa.outline.edges.size(), pb.outline.edges.size());
        EXPECT_EQ(pa.grain.has_value(), pb.grain.has_value());
        EXPECT_EQ(pa.fold.has_value(), pb.fold.has_value());
        EXPECT_EQ(pa.placement.has_value(), pb.placement.has_value());
        if (pa.placement && pb.placement) {
            EXPECT_EQ(pa.placement->rotation_deg, pb.placement->rotation_deg);
        }
    }
    ASSERT_EQ(a.seams.size(), b.seams.size());
    for (std::size_t i = 0; i < a.seams.size(); ++i) {
        EXPECT_EQ(a.seams[i].a.piece, b.seams[i].a.piece);
        EXPECT_EQ(a.seams[i].a.first_edge, b.seams[i].a.first_edge);
        EXPECT_EQ(a.seams[i].b.count, b.seams[i].b.count);
        EXPECT_EQ(a.seams[i].direction, b.seams[i].direction);
    }
    EXPECT_EQ(to_json(a)["bindings"], to_json(b)["bindings"]);
}

/// Largest distance moved by a named point, grain end, notch offset or translation.
double max_point_deviation(const Pattern& a, const Pattern& b) {
    double d = 0;
    for (std::size_t i = 0; i < a.pieces.size(); ++i) {
        const Piece &pa = a.pieces[i], &pb = b.pieces[i];
        for (const auto& [k, v] : pa.points) {
            d = std::max(d, distance(v, pb.points.at(k)));
        }
        for (std::size_t n = 0; n < pa.notches.size(); ++n) {
            d = std::max(d, std::abs(pa.notches[n].offset - pb.notches[n].offset));
        }
        if (pa.grain) {
            d = std::max({d, distance(pa.grain->from, pb.grain->from),
                          distance(pa.grain->to, pb.grain->to)});
        }
        if (pa.placement) {
            for (int k = 0; k < 3; ++k) {
                d = std::max(d,
                             std::abs(pa.placement->translation[k] - pb.placement->translation[k]));
            }
        }
    }
    return d;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void raw_sql(const std::string& path, const std::string& sql) {
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
    char* err = nullptr;
    const int rc = sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &err);
    EXPECT_EQ(rc, SQLITE_OK) << (err ? err : "");
    sqlite3_free(err);
    EXPECT_EQ(sqlite3_close(db), SQLITE_OK);
}

}  // namespace

TEST(PatternCompression, BlobDecodesToTheQuantisedPatternExactly) {
    const Pattern p = two_piece_pattern();
    CompressionReport rep;
    const std::vector<std::uint8_t> blob = compress_pattern(p, {}, &rep);
    const Pattern back = decompress_pattern(blob, "blob");
    EXPECT_EQ(to_json(back), to_json(quantised_pattern(p)));
    EXPECT_LE(max_edge_deviation(p, back), 0.001);
    EXPECT_LE(rep.max_error_mm, 0.001);
    EXPECT_GT(rep.quantised_numbers, 20u);
    // Exact numbers (measurements not on the grid) survive bit for bit.
    Pattern odd = p;
    odd.measurements_used["neck"] = 371.123456789;
    odd.pieces[0].placement->rotation_deg = {0.1, 12.345678901, 0};
    const Pattern odd_back = decompress_pattern(compress_pattern(odd), "blob");
    EXPECT_EQ(odd_back.measurements_used.at("neck"), 371.123456789);
    EXPECT_EQ(odd_back.pieces[0].placement->rotation_deg[1], 12.345678901);
}

TEST(PatternCompression, HalfCircleArcKeepsExactCoordinates) {
    // An arc of radius exactly half its chord: rounding the end points by δ would move its centre
    // by about √(2·r·δ) (0.2 mm here), so the encoder must keep this edge exact.
    Pattern p = two_piece_pattern();
    p.pieces[0].outline.edges[2] = {Arc{{200, 300}, {0.0004, 300}, 100.0000004, false, true}, ""};
    p.pieces[0].outline.edges[3].curve = Line{{0.0004, 300}, {0, 0}};
    CompressionReport rep;
    const Pattern back = decompress_pattern(compress_pattern(p, {}, &rep), "blob");
    EXPECT_GE(rep.exact_edges, 1u);
    EXPECT_LE(max_edge_deviation(p, back), 0.005);
}

TEST(PatternCompression, DamagedBlobsAreInvalidInput) {
    std::vector<std::uint8_t> blob = compress_pattern(two_piece_pattern());
    expect_invalid([&] { decompress_pattern(blob.data(), 3, "x.sqlite: pattern 'p'"); },
                   {"x.sqlite: pattern 'p'", "bad magic"});
    std::vector<std::uint8_t> cut(blob.begin(), blob.begin() + blob.size() / 2);
    expect_invalid([&] { decompress_pattern(cut, "pattern 'p'"); }, {"pattern 'p'", "damaged"});
    blob[3] = 9;
    expect_invalid([&] { decompress_pattern(blob, "pattern 'p'"); }, {"format 9"});

    // A frame header claiming 2 GiB for one byte of content (found by fuzz_pattern_blob: the
    // decoder zero-filled the claimed size first): refused before anything is allocated.
    std::vector<std::uint8_t> bomb = {'T',  'P',  'Z',  pattern_blob_format,
                                      0x28, 0xB5, 0x2F, 0xFD,  // zstd magic
                                      0xE0,                    // single segment, 8-byte size
                                      0,    0,    0,    0x80,
                                      0,    0,    0,    0,     // 2^31 bytes
                                      0x09, 0,    0,    'x'};  // last block, raw, 1 byte
    expect_invalid([&] { decompress_pattern(bomb, "pattern 'p'"); },
                   {"pattern 'p'", "claims 2147483648 bytes, more than its 17 compressed bytes"});
}

TEST(PatternDatabase, RoundTripOfEverySharedPattern) {
    const std::vector<std::string> files = tapeline_test::shared_pattern_files();
    if (files.empty()) {
        GTEST_SKIP() << "shared pattern data absent";
    }
    TempDir dir;
    const std::string path = dir.file("patterns.sqlite");
    std::vector<Pattern> originals;
    std::size_t json_total = 0, stored_total = 0, plain_zstd_total = 0;
    double import_s = 0, store_s = 0, worst_error = 0;
    {
        DatabaseOptions opts;
        opts.compression.measure_plain_zstd = true;
        PatternDatabase db(path, opts);
        EXPECT_TRUE(db.open_report().created);
        EXPECT_EQ(db.schema_version(), pattern_database_schema_version);
        for (const std::string& f : files) {
            const auto t0 = std::chrono::steady_clock::now();
            originals.push_back(tapeline_test::load_shared_pattern(f));
            import_s += seconds_since(t0);
            const StoreReport rep = db.store(originals.back());
            store_s += rep.seconds;
            json_total += rep.compression.json_bytes;
            stored_total += rep.compression.stored_bytes;
            plain_zstd_total += rep.compression.json_zstd_bytes;
            EXPECT_FALSE(rep.replaced);
            EXPECT_LE(rep.compression.max_error_mm, 0.001) << f;
            std::printf(
                "  %-32s json %7zu B  stored %6zu B  ratio %5.1f  (zstd of json %5.1f)  "
                "exact edges %zu  store %.1f ms\n",
                originals.back().name.c_str(), rep.compression.json_bytes,
                rep.compression.stored_bytes, rep.compression.ratio,
                double(rep.compression.json_bytes) / rep.compression.json_zstd_bytes,
                rep.compression.exact_edges, 1e3 * rep.seconds);
        }
    }
    const auto t0 = std::chrono::steady_clock::now();
    PatternDatabase db(path);
    EXPECT_FALSE(db.open_report().created);
    ASSERT_EQ(db.count(), files.size());
    for (const Pattern& orig : originals) {
        const Pattern back = db.load(orig.name);
        const double err =
            std::max(max_edge_deviation(orig, back), max_point_deviation(orig, back));
        worst_error = std::max(worst_error, err);
        EXPECT_LE(err, 0.01) << orig.name;
        expect_same_metadata(orig, back);
        // The stored geometry is exactly the quantised copy: nothing else is lost.
        EXPECT_EQ(to_json(back), to_json(quantised_pattern(orig))) << orig.name;
    }
    const double load_s = seconds_since(t0);
    EXPECT_EQ(db.integrity_check(), "ok");
    sqlite3_exec(db.handle(), "PRAGMA wal_checkpoint(TRUNCATE)", nullptr, nullptr, nullptr);
    const auto db_bytes = std::filesystem::file_size(path);
    std::printf(
        "%zu patterns: json %zu B, stored blobs %zu B (ratio %.2f; zstd of plain json "
        "alone %.2f), database file %ju B; worst round-trip error %.2g mm; import %.0f "
        "ms, store %.0f ms, load all %.0f ms\n",
        files.size(), json_total, stored_total, double(json_total) / stored_total,
        double(json_total) / plain_zstd_total, std::uintmax_t(db_bytes), worst_error,
        1e3 * import_s, 1e3 * store_s, 1e3 * load_s);
    EXPECT_GT(double(json_total) / stored_total, 5.0);
}

TEST(PatternDatabase, SearchByEachField) {
    TempDir dir;
    PatternDatabase db(dir.file("db.sqlite"));
    auto make = [](std::string name, std::string designer, std::string type, std::string size,
                   std::vector<std::string> tags) {
        Pattern p = two_piece_pattern();
        p.name = std::move(name);
        p.designer = std::move(designer);
        p.garment_type = std::move(type);
        p.size = std::move(size);
        p.tags = std::move(tags);
        return p;
    };
    db.store(make("Summer skirt", "Ada", "skirt", "36", {"summer", "easy"}));
    db.store(make("Winter skirt", "Bo", "skirt", "42", {"winter"}));
    db.store(make("Basic tee", "Ada Lovelace", "tee", "36", {"easy", "basic"}));
    db.store(make("100%_cotton tee", "Cy", "tee", "S", {}));
    auto names = [&](const PatternQuery& q) {
        std::vector<std::string> out;
        for (const PatternSummary& s : db.search(q)) {
            out.push_back(s.name);
        }
        return out;
    };
    using V = std::vector<std::string>;
    EXPECT_EQ(names({}), (V{"100%_cotton tee", "Basic tee", "Summer skirt", "Winter skirt"}));
    EXPECT_EQ(names({"SKIRT", "", "", "", {}}), (V{"Summer skirt", "Winter skirt"}));
    EXPECT_EQ(names({"%", "", "", "", {}}), (V{"100%_cotton tee"}));  // wildcards are literal
    EXPECT_EQ(names({"%_c", "", "", "", {}}), (V{"100%_cotton tee"}));
    EXPECT_TRUE(names({"0_c", "", "", "", {}}).empty());
    EXPECT_EQ(names({"", "ada", "", "", {}}), (V{"Basic tee", "Summer skirt"}));
    EXPECT_EQ(names({"", "", "tee", "", {}}), (V{"100%_cotton tee", "Basic tee"}));
    EXPECT_EQ(names({"", "", "", "36", {}}), (V{"Basic tee", "Summer skirt"}));
    EXPECT_EQ(names({"", "", "", "", {"easy"}}), (V{"Basic tee", "Summer skirt"}));
    EXPECT_EQ(names({"", "", "", "", {"easy", "basic"}}), (V{"Basic tee"}));
    EXPECT_EQ(names({"", "", "skirt", "36", {"summer"}}), (V{"Summer skirt"}));
    EXPECT_TRUE(names({"", "", "dress", "", {}}).empty());
    const std::vector<PatternSummary> all = db.list();
    ASSERT_EQ(all.size(), 4u);
    EXPECT_EQ(all[1].tags, (V{"basic", "easy"}));
    EXPECT_EQ(all[1].designer, "Ada Lovelace");
    EXPECT_EQ(all[1].pieces, 2u);
    EXPECT_EQ(all[1].seams, 1u);
    EXPECT_GT(all[1].json_bytes, all[1].stored_bytes);
    EXPECT_EQ(all[1].updated.size(), 20u);  // 2024-01-02T03:04:05Z
    EXPECT_TRUE(db.remove("Basic tee"));
    EXPECT_FALSE(db.remove("Basic tee"));
    EXPECT_EQ(names({"", "", "", "", {"basic"}}), V{});
}

TEST(PatternDatabase, ErrorsNameWhatAndWhere) {
    TempDir dir;
    const std::string path = dir.file("db.sqlite");
    {
        PatternDatabase db(path);
        Pattern p = two_piece_pattern();
        db.store(p);
        expect_invalid([&] { db.store(p); }, {path, "'test pattern'", "already stored", "replace"});
        p.designer = "someone else";
        p.tags = {"b", "a", "a"};
        EXPECT_TRUE(db.store(p, {true}).replaced);
        EXPECT_EQ(db.load("test pattern").designer, "someone else");
        EXPECT_EQ(db.list().at(0).tags, (std::vector<std::string>{"a", "b"}));
        EXPECT_EQ(db.count(), 1u);
        Pattern nameless = p;
        nameless.name.clear();
        expect_invalid([&] { db.store(nameless); }, {path, "without a name"});
        expect_invalid([&] { db.load("nope"); }, {path, "no pattern named 'nope'", "1 stored"});
        EXPECT_FALSE(db.find("nope").has_value());
        // A damaged blob: load names the file and the pattern.
        sqlite3_exec(db.handle(), "UPDATE patterns SET data = x'54505A0100'", nullptr, nullptr,
                     nullptr);
        expect_invalid([&] { db.load("test pattern"); }, {path, "pattern 'test pattern'"});
    }
    {
        PatternDatabase ro(path, {true});
        expect_invalid([&] { ro.store(two_piece_pattern(), {true}); }, {path, "read-only"});
    }
    // Not a database at all.
    const std::string junk = dir.file("junk.sqlite");
    std::string bytes(8192, '\0');
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        bytes[i] = char((i * 7919) % 251);
    }
    tapeline_test::write_text(junk, bytes);
    expect_invalid([&] { PatternDatabase db(junk); }, {junk, "not a database"});
    // A truncated copy of a real database (header kept, pages cut).
    const std::string cut = dir.file("cut.sqlite");
    {
        PatternDatabase big(cut);
        for (int i = 0; i < 40; ++i) {
            Pattern p = two_piece_pattern();
            p.name = "p" + std::to_string(i);
            p.tags = {std::string(2000, char('a' + i % 26))};
            big.store(p);
        }
        sqlite3_exec(big.handle(), "PRAGMA wal_checkpoint(TRUNCATE)", nullptr, nullptr, nullptr);
    }
    std::filesystem::resize_file(cut, std::filesystem::file_size(cut) / 2);
    expect_invalid(
        [&] {
            PatternDatabase db(cut);
            for (const PatternSummary& s : db.list()) {
                db.load(s.name);
            }
        },
        {cut, "damaged"});
    // Another program's SQLite file.
    const std::string foreign = dir.file("foreign.sqlite");
    raw_sql(foreign, "CREATE TABLE contacts(name TEXT)");
    expect_invalid([&] { PatternDatabase db(foreign); }, {foreign, "not a Tapeline pattern"});
    raw_sql(foreign, "PRAGMA application_id=1234");
    expect_invalid([&] { PatternDatabase db(foreign); }, {foreign, "another program"});
    // A database from the future.
    raw_sql(path, "PRAGMA user_version=99");
    expect_invalid([&] { PatternDatabase db(path); },
                   {path, "schema version 99", "newer", "up to version 2"});
    // Missing file when not creating.
    expect_invalid([&] { PatternDatabase db(dir.file("none.sqlite"), {true}); },
                   {"none.sqlite", "no pattern database"});
}

TEST(PatternDatabase, MigratesAVersion1File) {
    const auto& steps = pattern_database_migrations();
    ASSERT_FALSE(steps.empty());
    for (std::size_t i = 0; i < steps.size(); ++i) {
        EXPECT_EQ(steps[i].to_version, int(i) + 1);
    }
    EXPECT_EQ(steps.back().to_version, pattern_database_schema_version);

    TempDir dir;
    const std::string path = dir.file("v1.sqlite");
    const Pattern a = two_piece_pattern();
    const Pattern b = read_garmentcode(std::string(TAPELINE_DATA_DIR) +
                                       "/patterns/shirt_mean_specification.json");
    auto quote = [](const std::string& s) {
        std::string out = "'";
        for (char c : s) {
            out += c == '\'' ? std::string("''") : std::string(1, c);
        }
        return out + "'";
    };
    // Version 1 as an older Tapeline wrote it: plain JSON, tags as a JSON array column.
    raw_sql(path,
            "CREATE TABLE patterns(id INTEGER PRIMARY KEY, name TEXT NOT NULL UNIQUE, "
            "designer TEXT NOT NULL DEFAULT '', garment_type TEXT NOT NULL DEFAULT '', "
            "size TEXT NOT NULL DEFAULT '', tags TEXT NOT NULL DEFAULT '[]', json TEXT NOT NULL);"
            "INSERT INTO patterns(name, designer, garment_type, size, tags, json) VALUES(" +
                quote(a.name) + ", " + quote(a.designer) + ", " + quote(a.garment_type) + ", " +
                quote(a.size) + ", " + quote(nlohmann::json(a.tags).dump()) + ", " +
                quote(to_json(a).dump()) + ");" +
                "INSERT INTO patterns(name, designer, garment_type, size, tags, json) VALUES(" +
                quote(b.name) + ", " + quote(b.designer) + ", " + quote(b.garment_type) + ", " +
                quote(b.size) + ", " + quote(nlohmann::json(b.tags).dump()) + ", " +
                quote(to_json(b).dump()) + ");" + "PRAGMA user_version=1;");
    // Read-only refuses to upgrade.
    expect_invalid([&] { PatternDatabase db(path, {true}); },
                   {path, "schema version 1", "needs upgrading"});
    {
        PatternDatabase db(path);
        EXPECT_EQ(db.open_report().version_before, 1);
        EXPECT_EQ(db.open_report().version_after, 2);
        EXPECT_EQ(db.schema_version(), 2);
        ASSERT_EQ(db.count(), 2u);
        for (const Pattern* orig : {&a, &b}) {
            const Pattern back = db.load(orig->name);
            expect_same_metadata(*orig, back);
            EXPECT_LE(max_edge_deviation(*orig, back), 0.01);
        }
        EXPECT_EQ(db.search({"", "", "", "", {"garmentcode"}}).size(), 1u);
        EXPECT_EQ(db.search({"", "", "skirt", "M", {}}).size(), 1u);
        EXPECT_EQ(db.integrity_check(), "ok");
        EXPECT_EQ(internal::sql_integer(db.handle(), path,
                                        "SELECT count(*) FROM sqlite_master WHERE "
                                        "name='patterns_v1'"),
                  0);
        EXPECT_EQ(internal::sql_integer(db.handle(), path, "PRAGMA application_id"),
                  pattern_database_application_id);
    }
    // Opening again is a no-op.
    PatternDatabase again(path);
    EXPECT_EQ(again.open_report().version_before, 2);

    // A v1 row whose JSON is broken: the migration fails as a whole and leaves the v1 file.
    const std::string bad = dir.file("bad_v1.sqlite");
    raw_sql(bad,
            "CREATE TABLE patterns(id INTEGER PRIMARY KEY, name TEXT NOT NULL UNIQUE, "
            "designer TEXT NOT NULL DEFAULT '', garment_type TEXT NOT NULL DEFAULT '', "
            "size TEXT NOT NULL DEFAULT '', tags TEXT NOT NULL DEFAULT '[]', json TEXT NOT NULL);"
            "INSERT INTO patterns(name, json) VALUES('broken', '{\"format\": ');"
            "PRAGMA user_version=1;");
    expect_invalid([&] { PatternDatabase db(bad); }, {bad, "v1 pattern 'broken'", "malformed"});
    sqlite3* raw = nullptr;
    ASSERT_EQ(sqlite3_open(bad.c_str(), &raw), SQLITE_OK);
    EXPECT_EQ(internal::sql_integer(raw, bad, "PRAGMA user_version"), 1);
    EXPECT_EQ(internal::sql_integer(raw, bad, "SELECT count(*) FROM patterns"), 1);
    EXPECT_EQ(sqlite3_close(raw), SQLITE_OK);
}

TEST(PatternDatabase, DefaultPathFollowsXdg) {
    const char* old_xdg = std::getenv("XDG_DATA_HOME");
    const char* old_home = std::getenv("HOME");
    const std::string saved_xdg = old_xdg ? old_xdg : "", saved_home = old_home ? old_home : "";
    ::setenv("XDG_DATA_HOME", "/data/u", 1);
    EXPECT_EQ(default_pattern_database_path(), "/data/u/tapeline/patterns.sqlite");
    ::setenv("XDG_DATA_HOME", "relative/ignored", 1);
    ::setenv("HOME", "/home/u", 1);
    EXPECT_EQ(default_pattern_database_path(), "/home/u/.local/share/tapeline/patterns.sqlite");
    ::unsetenv("XDG_DATA_HOME");
    ::unsetenv("HOME");
    expect_invalid([] { default_pattern_database_path(); }, {"HOME", "give a database path"});
    old_xdg ? ::setenv("XDG_DATA_HOME", saved_xdg.c_str(), 1) : ::unsetenv("XDG_DATA_HOME");
    old_home ? ::setenv("HOME", saved_home.c_str(), 1) : ::unsetenv("HOME");
    // The directory is created on first use.
    TempDir dir;
    PatternDatabase db(dir.file("a/b/patterns.sqlite"));
    EXPECT_TRUE(std::filesystem::exists(dir.file("a/b/patterns.sqlite")));
}

namespace {

/// In a forked child: stores copies of `sources` named "p00000", "p00001", ... until `limit`
/// (or forever), then exits 0; any exception exits 2. With `kill_at_row` > 0 the child kills
/// itself (SIGKILL) right after writing that row, inside its transaction.
[[noreturn]] void writer_child(const std::string& path, const std::vector<Pattern>& sources,
                               int first, int limit, std::size_t kill_at_row = 0) {
    try {
        DatabaseOptions options;
        std::size_t rows = 0;
        if (kill_at_row > 0) {
            options.after_row = [&rows, kill_at_row](std::size_t) {
                if (++rows == kill_at_row) {
                    ::raise(SIGKILL);
                }
            };
        }
        PatternDatabase db(path, options);
        for (int i = first; i < limit; ++i) {
            Pattern p = sources[std::size_t(i) % sources.size()];
            char name[16];
            std::snprintf(name, sizeof name, "p%05d", i);
            p.name = name;
            db.store(p);
        }
        ::_exit(0);
    } catch (...) {
        ::_exit(2);
    }
}

/// Runs `child` in a forked process and returns its wait status.
int run_forked(const std::function<void()>& child) {
    const pid_t pid = ::fork();
    if (pid == 0) {
        try {
            child();
        } catch (...) {
            ::_exit(2);
        }
        ::_exit(0);
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    return status;
}

bool killed(int status) {
    return WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL;
}

}  // namespace

TEST(PatternDatabase, WriterKilledMidLoopLeavesOnlyCompletePatterns) {
    TempDir dir;
    const std::string path = dir.file("killed.sqlite");
    const std::vector<Pattern> sources = test_patterns();
    { PatternDatabase create(path); }
    // Five writers in turn, each killed inside the transaction of a different pattern; each
    // continues the numbering where the database stands. The kill moment is a row count, so the
    // number of complete patterns is known exactly.
    std::size_t expected = 0;
    for (int round = 0; round < 5; ++round) {
        const int first = int(PatternDatabase(path, {true}).count());
        ASSERT_EQ(std::size_t(first), expected);
        const std::size_t kill_at = std::size_t(3 * round + 5);
        const pid_t child = ::fork();
        ASSERT_GE(child, 0);
        if (child == 0) {
            writer_child(path, sources, first, 1 << 30, kill_at);
        }
        int status = 0;
        ::waitpid(child, &status, 0);
        ASSERT_TRUE(killed(status)) << "the writer ended before it was killed: " << status;
        expected += kill_at - 1;  // the pattern being written when killed is not stored
    }
    PatternDatabase db(path);
    EXPECT_EQ(db.integrity_check(), "ok");
    const std::vector<PatternSummary> all = db.list();
    ASSERT_EQ(all.size(), expected);
    for (std::size_t i = 0; i < all.size(); ++i) {
        char name[16];
        std::snprintf(name, sizeof name, "p%05zu", i);
        ASSERT_EQ(all[i].name, name) << "patterns must be stored in order with no gap";
        const Pattern back = db.load(all[i].name);
        const Pattern& src = sources[i % sources.size()];
        EXPECT_EQ(back.pieces.size(), src.pieces.size());
        EXPECT_EQ(all[i].tags.size(), internal::unique_tags(src.tags).size());
        EXPECT_LE(max_edge_deviation(src, back), 0.01) << name;
    }
    // The database stays writable after the crash.
    Pattern extra = two_piece_pattern();
    extra.name = "after the crash";
    db.store(extra);
    EXPECT_EQ(db.count(), all.size() + 1);
}

TEST(PatternDatabase, ReadersReadWhileAWriterWrites) {
    TempDir dir;
    const std::string path = dir.file("concurrent.sqlite");
    const std::vector<Pattern> sources = test_patterns();
    const int initial = 10, total = 60;
    {
        PatternDatabase db(path);
        for (int i = 0; i < initial; ++i) {
            Pattern p = sources[std::size_t(i) % sources.size()];
            char name[16];
            std::snprintf(name, sizeof name, "p%05d", i);
            p.name = name;
            db.store(p);
        }
    }
    const pid_t writer = ::fork();
    ASSERT_GE(writer, 0);
    if (writer == 0) {
        writer_child(path, sources, initial, total);
    }
    std::vector<pid_t> readers;
    for (int r = 0; r < 2; ++r) {
        const pid_t pid = ::fork();
        ASSERT_GE(pid, 0);
        if (pid == 0) {
            // Exit codes: 0 = saw the writer finish with every snapshot consistent; 3 = a
            // snapshot lost a pattern; 4 = timeout; 2 = an exception.
            try {
                PatternDatabase db(path, {true});
                std::size_t last = 0;
                int rounds = 0;
                const auto t0 = std::chrono::steady_clock::now();
                while (seconds_since(t0) < 120) {
                    const std::vector<PatternSummary> all = db.list();
                    if (all.size() < last) {
                        ::_exit(3);
                    }
                    last = all.size();
                    for (const PatternSummary& s : all) {
                        if (db.load(s.name).pieces.size() != s.pieces) {
                            ::_exit(3);
                        }
                    }
                    ++rounds;
                    if (last == std::size_t(total) && rounds > 1) {
                        ::_exit(0);
                    }
                }
                ::_exit(4);
            } catch (...) {
                ::_exit(2);
            }
        }
        readers.push_back(pid);
    }
    int status = 0;
    ::waitpid(writer, &status, 0);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "writer status " << status;
    for (const pid_t pid : readers) {
        ::waitpid(pid, &status, 0);
        EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "reader status " << status;
    }
    PatternDatabase db(path);
    EXPECT_EQ(db.count(), std::size_t(total));
    EXPECT_EQ(db.integrity_check(), "ok");
}

// --- batches, fault injection, concurrent creation, read-only files ------------------------------

namespace {

/// `n` patterns named "<prefix>00" ... from the in-repo sources, with `designer`.
std::vector<Pattern> batch(const std::string& prefix, std::size_t n, const std::string& designer) {
    static const std::vector<Pattern> sources = {
        two_piece_pattern(),
        read_freesewing(std::string(TAPELINE_DATA_DIR) + "/patterns/aaron_cisFemaleAdult36.json"),
        read_garmentcode(std::string(TAPELINE_DATA_DIR) +
                         "/patterns/shirt_mean_specification.json")};
    std::vector<Pattern> out;
    for (std::size_t i = 0; i < n; ++i) {
        Pattern p = sources[i % sources.size()];
        char name[32];
        std::snprintf(name, sizeof name, "%s%02zu", prefix.c_str(), i);
        p.name = name;
        p.designer = designer;
        out.push_back(std::move(p));
    }
    return out;
}

/// Options whose hook kills the process right after row `row` of a transaction.
DatabaseOptions killing_at(std::size_t row) {
    DatabaseOptions o;
    o.after_row = [row](std::size_t written) {
        if (written == row) {
            ::raise(SIGKILL);
        }
    };
    return o;
}

void checkpoint(const std::string& path) {
    raw_sql(path, "PRAGMA wal_checkpoint(TRUNCATE)");
}

std::string v1_insert(const Pattern& p) {
    auto quote = [](const std::string& s) {
        std::string out = "'";
        for (char c : s) {
            out += c == '\'' ? std::string("''") : std::string(1, c);
        }
        return out + "'";
    };
    return "INSERT INTO patterns(name, designer, garment_type, size, tags, json) VALUES(" +
           quote(p.name) + ", " + quote(p.designer) + ", " + quote(p.garment_type) + ", " +
           quote(p.size) + ", " + quote(nlohmann::json(p.tags).dump()) + ", " +
           quote(to_json(p).dump()) + ");";
}

}  // namespace

TEST(PatternDatabase, BatchIsAllOrNothing) {
    TempDir dir;
    const std::string path = dir.file("batch.sqlite");
    PatternDatabase db(path);
    db.store_all(batch("old", 3, "d"));
    // The last pattern of the batch is already stored: nothing of the batch is.
    std::vector<Pattern> b = batch("new", 5, "d");
    b.back().name = "old01";
    expect_invalid([&] { db.store_all(b); }, {path, "'old01' is already stored", "nothing was"});
    EXPECT_EQ(db.count(), 3u);
    // Two patterns of the batch with one name.
    b.back().name = "new00";
    expect_invalid([&] { db.store_all(b); }, {path, "two patterns of the batch", "'new00'"});
    EXPECT_EQ(db.count(), 3u);
    // A process killed while writing the fourth of five rows stores none of them.
    const int status =
        run_forked([&] { PatternDatabase(path, killing_at(4)).store_all(batch("k", 5, "d")); });
    EXPECT_TRUE(killed(status)) << status;
    EXPECT_EQ(db.count(), 3u);
    EXPECT_FALSE(db.contains("k00"));
    // The rerun completes.
    EXPECT_EQ(db.store_all(batch("k", 5, "d")).size(), 5u);
    EXPECT_EQ(db.count(), 8u);
}

// SIGKILL at a row chosen at random inside import, replace and migrate, half the time followed by
// a power cut (the WAL truncated at a random byte): the file passes the integrity check, each
// batch is wholly there or absent, and running the operation again completes.
TEST(PatternDatabase, FaultInjectionHundredTrials) {
    TempDir dir;
    std::mt19937 rng(20261125);
    const std::size_t n = 8;
    int kills = 0, truncations = 0;
    for (int trial = 0; trial < 100; ++trial) {
        SCOPED_TRACE("trial " + std::to_string(trial));
        const std::string path = dir.file("t" + std::to_string(trial) + ".sqlite");
        const int kind = trial % 3;  // 0 import, 1 replace, 2 migrate
        const std::size_t row = 1 + rng() % n;
        if (kind == 0) {
            PatternDatabase(path).store_all(batch("base", 2, "d"));
        } else if (kind == 1) {
            PatternDatabase(path).store_all(batch("p", n, "old"));
        } else {
            std::string sql =
                "CREATE TABLE patterns(id INTEGER PRIMARY KEY, name TEXT NOT NULL UNIQUE, "
                "designer TEXT NOT NULL DEFAULT '', garment_type TEXT NOT NULL DEFAULT '', "
                "size TEXT NOT NULL DEFAULT '', tags TEXT NOT NULL DEFAULT '[]', "
                "json TEXT NOT NULL);";
            for (const Pattern& p : batch("p", n, "v1")) {
                sql += v1_insert(p);
            }
            raw_sql(path, sql + "PRAGMA journal_mode=WAL; PRAGMA user_version=1;");
        }
        checkpoint(path);
        const int status = run_forked([&] {
            if (kind == 0) {
                PatternDatabase(path, killing_at(row)).store_all(batch("p", n, "d"));
            } else if (kind == 1) {
                StoreOptions replace;
                replace.replace = true;
                PatternDatabase(path, killing_at(row)).store_all(batch("p", n, "new"), replace);
            } else {
                PatternDatabase db(path, killing_at(row));
            }
        });
        ASSERT_TRUE(killed(status)) << status;
        ++kills;
        const std::string wal = path + "-wal";
        if (trial % 2 == 1 && std::filesystem::exists(wal)) {
            const auto size = std::filesystem::file_size(wal);
            std::filesystem::resize_file(wal, size ? rng() % size : 0);
            ++truncations;
        }
        {
            sqlite3* raw = nullptr;
            ASSERT_EQ(sqlite3_open(path.c_str(), &raw), SQLITE_OK);
            SCOPED_TRACE("after the kill");
            EXPECT_EQ(internal::sql_integer(raw, path, "SELECT count(*) FROM patterns"),
                      std::int64_t(kind == 0 ? 2 : n));
            if (kind == 2) {
                EXPECT_EQ(internal::sql_integer(raw, path, "PRAGMA user_version"), 1);
                EXPECT_EQ(internal::sql_integer(raw, path,
                                                "SELECT count(*) FROM sqlite_master WHERE "
                                                "name IN ('patterns_v1', 'pattern_tags')"),
                          0);
            }
            {
                internal::SqlStatement check(raw, path, "PRAGMA integrity_check");
                ASSERT_TRUE(check.step());
                EXPECT_EQ(check.text(0), "ok");
            }  // finalized before the close, which leaves a connection open while any is not
            ASSERT_EQ(sqlite3_close(raw), SQLITE_OK);
        }
        // The rerun completes and leaves every pattern whole.
        PatternDatabase db(path);
        if (kind == 0) {
            db.store_all(batch("p", n, "d"));
        } else if (kind == 1) {
            for (const PatternSummary& s : db.list()) {
                EXPECT_EQ(s.designer, "old") << s.name;
            }
            StoreOptions replace;
            replace.replace = true;
            db.store_all(batch("p", n, "new"), replace);
        }
        EXPECT_EQ(db.schema_version(), pattern_database_schema_version);
        EXPECT_EQ(db.count(), kind == 0 ? n + 2 : n);
        const std::vector<Pattern> expected = batch("p", n, "");
        for (std::size_t i = 0; i < n; ++i) {
            const Pattern back = db.load(expected[i].name);
            EXPECT_EQ(back.pieces.size(), expected[i].pieces.size());
            EXPECT_EQ(back.designer, kind == 0 ? "d" : kind == 1 ? "new" : "v1");
        }
        EXPECT_EQ(db.integrity_check(), "ok");
    }
    EXPECT_EQ(kills, 100);
    EXPECT_GT(truncations, 20);
}

// Eight processes create the same new file at once, ten times over: every one opens it and
// stores its pattern (no "database is locked", no half-created schema seen).
TEST(PatternDatabase, ConcurrentCreationOfOneFile) {
    TempDir dir;
    for (int round = 0; round < 10; ++round) {
        const std::string path = dir.file("race" + std::to_string(round) + ".sqlite");
        int go[2];
        ASSERT_EQ(::pipe(go), 0);
        std::vector<pid_t> children;
        for (int c = 0; c < 8; ++c) {
            const pid_t pid = ::fork();
            if (pid == 0) {
                ::close(go[1]);
                char byte;
                if (::read(go[0], &byte, 1) != 0) {
                    ::_exit(3);
                }
                try {
                    PatternDatabase db(path);
                    Pattern p = two_piece_pattern();
                    p.name = "c" + std::to_string(c);
                    db.store(p);
                    ::_exit(0);
                } catch (const std::exception& e) {
                    std::fprintf(stderr, "child %d: %s\n", c, e.what());
                    ::_exit(2);
                }
            }
            children.push_back(pid);
        }
        ::close(go[0]);
        ::close(go[1]);  // end of file releases every child at once
        for (const pid_t pid : children) {
            int status = 0;
            ::waitpid(pid, &status, 0);
            EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0)
                << "round " << round << ": status " << status;
        }
        PatternDatabase db(path, {true});
        EXPECT_EQ(db.count(), 8u);
        EXPECT_EQ(db.schema_version(), pattern_database_schema_version);
    }
}

// A WAL database in a directory the reader cannot write (another user's, or read-only media):
// mode=ro cannot create the WAL index, so the file is opened immutable and the report says so.
TEST(PatternDatabase, ReadOnlyDirectoryIsReadImmutable) {
    TempDir dir;
    const std::filesystem::path sub = dir.path / "ro";
    std::filesystem::create_directories(sub);
    const std::string path = (sub / "patterns.sqlite").string();
    PatternDatabase(path).store_all(batch("p", 3, "d"));
    {
        PatternDatabase plain(path, {true});
        EXPECT_FALSE(plain.open_report().immutable);
        EXPECT_EQ(plain.count(), 3u);
    }
    // A read-only connection leaves an empty WAL and its index behind; without them the next
    // reader has to create both.
    ASSERT_EQ(
        std::filesystem::exists(path + "-wal") ? std::filesystem::file_size(path + "-wal") : 0u,
        0u);
    std::filesystem::remove(path + "-wal");
    std::filesystem::remove(path + "-shm");
    std::filesystem::permissions(
        sub, std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec |
                 std::filesystem::perms::group_read | std::filesystem::perms::group_exec |
                 std::filesystem::perms::others_read | std::filesystem::perms::others_exec);
    // Root ignores directory permissions: the reader drops to an unprivileged user.
    const int status = run_forked([&] {
        if (::geteuid() == 0 && (::setgid(65534) != 0 || ::setuid(65534) != 0)) {
            ::_exit(4);
        }
        PatternDatabase db(path, {true});
        if (!db.open_report().immutable) {
            ::_exit(5);
        }
        if (db.count() != 3 || db.load("p01").pieces.empty()) {
            ::_exit(6);
        }
    });
    std::filesystem::permissions(sub, std::filesystem::perms::owner_all,
                                 std::filesystem::perm_options::add);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "status " << status;
}
