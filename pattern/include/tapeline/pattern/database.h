// A pattern database in one embedded SQLite file.
//
// Where: `default_pattern_database_path()` ($XDG_DATA_HOME/tapeline/patterns.sqlite, else
// ~/.local/share/tapeline/patterns.sqlite) or any path. What: one row per pattern with its name
// (unique), designer, garment type, size and counts in plain columns for search, its tags in a
// side table, and its geometry as a compressed blob (compression.h: 0.001 mm grid, varint deltas,
// zstd). Safety: WAL journal, every write in one transaction (BEGIN IMMEDIATE ... COMMIT), so a
// process killed at any moment leaves the file consistent, holding every pattern whose store()
// returned and no partial one; store_all() writes a batch in one transaction (all or none).
// Readers see a consistent snapshot while a writer writes. A read-only open uses SQLite's
// `mode=ro`, falling back to `immutable` where the WAL index cannot be created. Processes that
// create the same new file at once agree: the schema is created under the write lock, after
// checking again that no other process created it meanwhile.
// Synchronous=NORMAL by default: a killed process loses nothing, a power failure may lose the last
// transactions (DatabaseOptions::synchronous_full makes every commit durable).
//
// Schema versions (PRAGMA user_version) and the migrations that reach them, applied in order in one
// transaction when a file is opened writable:
//   1  patterns(name, designer, garment_type, size, tags as a JSON array, json: the plain
//      "tapeline-pattern" JSON)
//   2  patterns(name, designer, garment_type, size, pieces, seams, json_bytes, data: compressed
//      blob, updated) + pattern_tags(pattern_id, tag) + indexes on the searched fields; every v1
//      row is converted.
// A file from a newer schema is refused with a message saying so. PRAGMA application_id is set to
// 'TPLN' so that another program's SQLite file is refused rather than altered.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/pattern/compression.h>
#include <tapeline/pattern/io_json.h>
#include <tapeline/pattern/pattern.h>

#include <sqlite3.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace tapeline::pattern {

inline constexpr int pattern_database_schema_version = 2;
inline constexpr std::int32_t pattern_database_application_id = 0x54504C4E;  // "TPLN"

/// How PatternDatabase opens and writes its file.
struct DatabaseOptions {
    bool read_only = false;          ///< never writes; refuses a file that needs migrating
    bool create = true;              ///< create the file and its directory when missing
    int busy_timeout_ms = 10000;     ///< how long a writer waits for another writer's lock
    bool synchronous_full = false;   ///< SQLite synchronous=FULL (else NORMAL under WAL)
    CompressionOptions compression;  ///< how stored patterns are compressed
    /// Called with the running count after each pattern row written inside a transaction
    /// (store, store_all, migration); fault-injection tests stop the process at a chosen row.
    std::function<void(std::size_t rows_written)> after_row;
};

/// How PatternDatabase::store treats an existing name.
struct StoreOptions {
    bool replace = false;  ///< overwrite a pattern of the same name instead of refusing
};

/// What storing one pattern did.
struct StoreReport {
    CompressionReport compression;  ///< sizes before and after compression
    bool replaced = false;          ///< a pattern of the same name was overwritten
    double seconds = 0;             ///< compression + transaction
};

/// One row of list() / search(): the searchable fields without decoding the geometry.
struct PatternSummary {
    /// Name, designer, garment type and size of the pattern.
    ///@{
    std::string name, designer, garment_type, size;
    ///@}
    std::vector<std::string> tags;  ///< the pattern's tags
    /// Piece and seam counts, size as JSON and as stored.
    ///@{
    std::size_t pieces = 0, seams = 0, json_bytes = 0, stored_bytes = 0;
    ///@}
    std::string updated;  ///< UTC, ISO 8601
};

/// Empty fields match anything. `name` and `designer` match a case-insensitive (ASCII)
/// substring; `garment_type` and `size` match exactly; every tag in `tags` must be present.
struct PatternQuery {
    /// Name and designer (substrings), garment type and size (exact).
    ///@{
    std::string name, designer, garment_type, size;
    ///@}
    std::vector<std::string> tags;  ///< every one must be present
};

/// What opening did to the file.
struct DatabaseOpenReport {
    bool created = false;  ///< the file did not exist
    /// Schema version found, and after migrating.
    ///@{
    int version_before = 0, version_after = 0;
    ///@}
    /// Read-only open of a WAL file whose shared-memory index (-shm) could be neither opened nor
    /// created (a read-only directory, another user's file): opened as immutable, so changes
    /// another process makes while this one reads are not seen.
    bool immutable = false;
};

/// The per-user default location (XDG base directories). Throws InvalidInput when neither
/// XDG_DATA_HOME (absolute) nor HOME is set.
inline std::string default_pattern_database_path() {
    const char* xdg = std::getenv("XDG_DATA_HOME");
    if (xdg && xdg[0] == '/') {  // the XDG spec says to ignore a relative value
        return std::string(xdg) + "/tapeline/patterns.sqlite";
    }
    const char* home = std::getenv("HOME");
    if (!home || !home[0]) {
        throw InvalidInput(
            "pattern database: neither XDG_DATA_HOME nor HOME is set, so there is no default "
            "location; give a database path");
    }
    return std::string(home) + "/.local/share/tapeline/patterns.sqlite";
}

namespace internal {

/// A prepared statement; every failure is an InvalidInput naming the database file.
class SqlStatement {
public:
    SqlStatement(sqlite3* db, const std::string& where, const std::string& sql)
        : db_(db), where_(where) {
        if (sqlite3_prepare_v2(db, sql.c_str(), int(sql.size()), &st_, nullptr) != SQLITE_OK) {
            fail("preparing '" + sql + "'");
        }
    }
    ~SqlStatement() { sqlite3_finalize(st_); }
    SqlStatement(const SqlStatement&) = delete;
    SqlStatement& operator=(const SqlStatement&) = delete;

    SqlStatement& bind(int i, const std::string& s) {
        check(sqlite3_bind_text(st_, i, s.data(), int(s.size()), SQLITE_TRANSIENT));
        return *this;
    }
    SqlStatement& bind(int i, std::int64_t v) {
        check(sqlite3_bind_int64(st_, i, v));
        return *this;
    }
    SqlStatement& bind(int i, const std::vector<std::uint8_t>& b) {
        check(sqlite3_bind_blob(st_, i, b.data(), int(b.size()), SQLITE_TRANSIENT));
        return *this;
    }
    /// True while a row is available.
    bool step() {
        const int rc = sqlite3_step(st_);
        if (rc == SQLITE_ROW) {
            return true;
        }
        if (rc == SQLITE_DONE) {
            return false;
        }
        fail("executing '" + std::string(sqlite3_sql(st_)) + "'");
    }
    void reset() {
        sqlite3_reset(st_);
        sqlite3_clear_bindings(st_);
    }
    std::string text(int c) const {
        const auto* t = sqlite3_column_text(st_, c);
        return t ? std::string(reinterpret_cast<const char*>(t),
                               std::size_t(sqlite3_column_bytes(st_, c)))
                 : std::string();
    }
    std::int64_t integer(int c) const { return sqlite3_column_int64(st_, c); }
    std::pair<const void*, std::size_t> blob(int c) const {
        const void* p = sqlite3_column_blob(st_, c);
        return {p, std::size_t(sqlite3_column_bytes(st_, c))};
    }

private:
    void check(int rc) {
        if (rc != SQLITE_OK) {
            fail("binding a value");
        }
    }
    [[noreturn]] void fail(const std::string& what) const;

    sqlite3* db_;
    std::string where_;
    sqlite3_stmt* st_ = nullptr;
};

/// The message for a failed SQLite call, with a plain explanation for damaged files.
inline std::string sqlite_message(sqlite3* db) {
    const int rc = sqlite3_errcode(db);
    std::string m = sqlite3_errmsg(db);
    if (rc == SQLITE_NOTADB || rc == SQLITE_CORRUPT) {
        m += " (the file is damaged or is not a SQLite database)";
    } else if (rc == SQLITE_BUSY || rc == SQLITE_LOCKED) {
        m += " (another process holds the write lock)";
    } else if (rc == SQLITE_READONLY) {
        m += " (opened read-only or no write permission)";
    }
    return m;
}

inline void SqlStatement::fail(const std::string& what) const {
    throw InvalidInput(where_ + ": " + what + ": " + sqlite_message(db_));
}

inline void sql_exec(sqlite3* db, const std::string& where, const std::string& sql) {
    char* err = nullptr;
    if (sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &err) != SQLITE_OK) {
        const std::string m = sqlite_message(db);
        sqlite3_free(err);
        throw InvalidInput(where + ": " + m + " (while running: " + sql.substr(0, 80) + ")");
    }
}

inline std::int64_t sql_integer(sqlite3* db, const std::string& where, const std::string& sql) {
    SqlStatement st(db, where, sql);
    return st.step() ? st.integer(0) : 0;
}

/// ROLLBACK unless commit() was called.
class SqlTransaction {
public:
    SqlTransaction(sqlite3* db, const std::string& where, const char* begin = "BEGIN IMMEDIATE")
        : db_(db), where_(where) {
        sql_exec(db, where, begin);
    }
    ~SqlTransaction() {
        if (!done_) {
            sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
        }
    }
    void commit() {
        sql_exec(db_, where_, "COMMIT");
        done_ = true;
    }

private:
    sqlite3* db_;
    std::string where_;
    bool done_ = false;
};

inline std::vector<std::string> unique_tags(const std::vector<std::string>& tags) {
    std::set<std::string> s(tags.begin(), tags.end());
    return {s.begin(), s.end()};
}

/// Inserts (or with `id` > 0, rewrites) pattern row `p` in schema 2; returns the row id.
inline std::int64_t write_pattern_row_v2(sqlite3* db, const std::string& where, const Pattern& p,
                                         const std::vector<std::uint8_t>& blob,
                                         std::size_t json_bytes, std::int64_t id) {
    if (id > 0) {
        SqlStatement up(db, where,
                        "UPDATE patterns SET designer=?2, garment_type=?3, size=?4, pieces=?5, "
                        "seams=?6, json_bytes=?7, data=?8, "
                        "updated=strftime('%Y-%m-%dT%H:%M:%SZ','now') WHERE id=?1");
        up.bind(1, id);
        up.bind(2, p.designer).bind(3, p.garment_type).bind(4, p.size);
        up.bind(5, std::int64_t(p.pieces.size())).bind(6, std::int64_t(p.seams.size()));
        up.bind(7, std::int64_t(json_bytes)).bind(8, blob);
        up.step();
        SqlStatement del(db, where, "DELETE FROM pattern_tags WHERE pattern_id=?1");
        del.bind(1, id).step();
    } else {
        SqlStatement ins(db, where,
                         "INSERT INTO patterns(name, designer, garment_type, size, pieces, seams, "
                         "json_bytes, data) VALUES(?1,?2,?3,?4,?5,?6,?7,?8)");
        ins.bind(1, p.name).bind(2, p.designer).bind(3, p.garment_type).bind(4, p.size);
        ins.bind(5, std::int64_t(p.pieces.size())).bind(6, std::int64_t(p.seams.size()));
        ins.bind(7, std::int64_t(json_bytes)).bind(8, blob);
        ins.step();
        id = sqlite3_last_insert_rowid(db);
    }
    SqlStatement tag(db, where, "INSERT INTO pattern_tags(pattern_id, tag) VALUES(?1, ?2)");
    for (const std::string& t : unique_tags(p.tags)) {
        tag.reset();
        tag.bind(1, id).bind(2, t).step();
    }
    return id;
}

}  // namespace internal

/// One step of the schema history: brings a database at `to_version - 1` to `to_version`.
struct DatabaseMigration {
    int to_version;    ///< schema version after the step
    const char* what;  ///< what the step changes, for messages
    /// Runs the step inside the caller's transaction.
    void (*apply)(sqlite3* db, const std::string& where, const DatabaseOptions& options);
};

/// The schema history, oldest first; the last step's version is pattern_database_schema_version.
inline const std::vector<DatabaseMigration>& pattern_database_migrations() {
    static const std::vector<DatabaseMigration> steps = {
        {1, "create the v1 table (plain JSON per pattern)",
         [](sqlite3* db, const std::string& where, const DatabaseOptions&) {
             internal::sql_exec(db, where,
                                "CREATE TABLE patterns(id INTEGER PRIMARY KEY, "
                                "name TEXT NOT NULL UNIQUE, designer TEXT NOT NULL DEFAULT '', "
                                "garment_type TEXT NOT NULL DEFAULT '', "
                                "size TEXT NOT NULL DEFAULT '', tags TEXT NOT NULL DEFAULT '[]', "
                                "json TEXT NOT NULL)");
         }},
        {2, "compressed geometry, tag table, search indexes",
         [](sqlite3* db, const std::string& where, const DatabaseOptions& options) {
             using internal::sql_exec;
             sql_exec(db, where, "ALTER TABLE patterns RENAME TO patterns_v1");
             sql_exec(db, where,
                      "CREATE TABLE patterns(id INTEGER PRIMARY KEY, name TEXT NOT NULL UNIQUE, "
                      "designer TEXT NOT NULL, garment_type TEXT NOT NULL, size TEXT NOT NULL, "
                      "pieces INTEGER NOT NULL, seams INTEGER NOT NULL, "
                      "json_bytes INTEGER NOT NULL, data BLOB NOT NULL, updated TEXT NOT NULL "
                      "DEFAULT (strftime('%Y-%m-%dT%H:%M:%SZ','now')))");
             sql_exec(db, where,
                      "CREATE TABLE pattern_tags(pattern_id INTEGER NOT NULL REFERENCES "
                      "patterns(id) ON DELETE CASCADE, tag TEXT NOT NULL, "
                      "PRIMARY KEY(pattern_id, tag)) WITHOUT ROWID");
             sql_exec(db, where,
                      "CREATE INDEX patterns_designer ON patterns(designer);"
                      "CREATE INDEX patterns_garment_type ON patterns(garment_type);"
                      "CREATE INDEX patterns_size ON patterns(size);"
                      "CREATE INDEX pattern_tags_tag ON pattern_tags(tag)");
             internal::SqlStatement rows(
                 db, where,
                 "SELECT name, designer, garment_type, size, tags, json FROM patterns_v1");
             std::size_t written = 0;
             while (rows.step()) {
                 const std::string name = rows.text(0);
                 const std::string row = where + ": v1 pattern '" + name + "'";
                 Pattern p = from_json(internal::parse_json(rows.text(5), row), row);
                 // The columns are what v1 searched on, so they win over the JSON copy.
                 p.name = name;
                 p.designer = rows.text(1);
                 p.garment_type = rows.text(2);
                 p.size = rows.text(3);
                 const internal::Json tags = internal::parse_json(rows.text(4), row + " tags");
                 if (!tags.is_array()) {
                     throw InvalidInput(row + ": tags column is not a JSON array");
                 }
                 p.tags.clear();
                 for (const auto& t : tags) {
                     if (!t.is_string()) {
                         throw InvalidInput(row + ": tags column holds a non-string");
                     }
                     p.tags.push_back(t.get<std::string>());
                 }
                 const std::size_t json_bytes = to_json(p).dump().size();
                 internal::write_pattern_row_v2(
                     db, where, p, compress_pattern(p, options.compression), json_bytes, 0);
                 if (options.after_row) {
                     options.after_row(++written);
                 }
             }
             sql_exec(db, where, "DROP TABLE patterns_v1");
         }},
    };
    return steps;
}

/// A SQLite file of compressed patterns, searchable by name, designer, garment type, size and
/// tags. Writes are transactions (all or nothing, even when the process is killed); several
/// processes may read and write the file at once (WAL). Every member that touches the file
/// throws InvalidInput naming it when SQLite fails.
class PatternDatabase {
public:
    /// Opens (creating when allowed) the database at `path` and migrates it to the current
    /// schema. Throws InvalidInput for a file that is damaged, not a pattern database, from a
    /// newer schema, or (read-only) from an older one.
    ///
    /// \throws InvalidInput also when the file is missing and `options.create` is off, its
    ///         directory cannot be created, or the file cannot be opened.
    explicit PatternDatabase(std::string path, DatabaseOptions options = {})
        : path_(std::move(path)), options_(std::move(options)) {
        open();
    }
    ~PatternDatabase() { sqlite3_close_v2(db_); }
    PatternDatabase(const PatternDatabase&) = delete;
    PatternDatabase& operator=(const PatternDatabase&) = delete;

    /// The database file.
    const std::string& path() const { return path_; }
    /// The file's schema version (pattern_database_schema_version after opening).
    int schema_version() const {
        return int(internal::sql_integer(db_, path_, "PRAGMA user_version"));
    }
    /// What opening did to the file.
    const DatabaseOpenReport& open_report() const { return open_report_; }

    /// Stores `p` under its name. A missing name, or an existing name without
    /// `options.replace`, is an InvalidInput.
    ///
    /// \throws InvalidInput also when the database is read-only, or as store_all.
    StoreReport store(const Pattern& p, const StoreOptions& options = {}) {
        return store_all({p}, options).front();
    }

    /// Stores every pattern in one transaction: all of them or, after any refusal, an error or
    /// a killed process, none. Two patterns of one batch with the same name are refused.
    ///
    /// \throws InvalidInput on a read-only database, a pattern without a name, a name given
    ///         twice in the batch or already stored without `options.replace`, bad compression
    ///         options, or a SQLite failure; nothing is stored then.
    /// \throws std::runtime_error when zstd fails to compress.
    std::vector<StoreReport> store_all(const std::vector<Pattern>& patterns,
                                       const StoreOptions& options = {}) {
        using namespace internal;
        const auto t0 = std::chrono::steady_clock::now();
        std::set<std::string> names;
        for (const Pattern& p : patterns) {
            if (p.name.empty()) {
                throw InvalidInput(path_ +
                                   ": cannot store a pattern without a name (set Pattern::name)");
            }
            if (!names.insert(p.name).second) {
                throw InvalidInput(path_ + ": two patterns of the batch are named '" + p.name +
                                   "'; nothing was stored");
            }
            require_writable("store pattern '" + p.name + "'");
        }
        std::vector<StoreReport> reports(patterns.size());
        std::vector<std::vector<std::uint8_t>> blobs;
        for (std::size_t i = 0; i < patterns.size(); ++i) {
            blobs.push_back(
                compress_pattern(patterns[i], options_.compression, &reports[i].compression));
        }
        SqlTransaction tx(db_, path_);
        for (std::size_t i = 0; i < patterns.size(); ++i) {
            const Pattern& p = patterns[i];
            const std::int64_t id = row_id(p.name);
            if (id > 0 && !options.replace) {
                throw InvalidInput(path_ + ": a pattern named '" + p.name +
                                   "' is already stored (store with replace to overwrite it)" +
                                   (patterns.size() > 1 ? "; nothing was stored" : ""));
            }
            reports[i].replaced = id > 0;
            write_pattern_row_v2(db_, path_, p, blobs[i], reports[i].compression.json_bytes, id);
            if (options_.after_row) {
                options_.after_row(i + 1);
            }
        }
        tx.commit();
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        for (StoreReport& r : reports) {
            r.seconds = seconds;
        }
        return reports;
    }

    /// The pattern named `name`, or nullopt.
    ///
    /// \throws InvalidInput when the stored blob cannot be decoded, or SQLite fails.
    std::optional<Pattern> find(const std::string& name) const {
        internal::SqlStatement st(db_, path_, "SELECT data FROM patterns WHERE name=?1");
        st.bind(1, name);
        if (!st.step()) {
            return std::nullopt;
        }
        const auto [data, size] = st.blob(0);
        Pattern p = decompress_pattern(data, size, path_ + ": pattern '" + name + "'");
        p.name = name;
        return p;
    }

    /// The pattern named `name`; InvalidInput when there is none.
    ///
    /// \throws InvalidInput when there is none, its blob cannot be decoded, or SQLite fails.
    Pattern load(const std::string& name) const {
        std::optional<Pattern> p = find(name);
        if (!p) {
            throw InvalidInput(path_ + ": no pattern named '" + name + "' (" +
                               std::to_string(count()) + " stored)");
        }
        return std::move(*p);
    }

    /// Whether a pattern named `name` is stored.
    bool contains(const std::string& name) const { return row_id(name) > 0; }

    /// Number of stored patterns.
    std::size_t count() const {
        return std::size_t(internal::sql_integer(db_, path_, "SELECT count(*) FROM patterns"));
    }

    /// Removes the pattern; false when there was none.
    ///
    /// \throws InvalidInput when the database is read-only, or SQLite fails.
    bool remove(const std::string& name) {
        require_writable("remove pattern '" + name + "'");
        internal::SqlTransaction tx(db_, path_);
        const std::int64_t id = row_id(name);
        if (id > 0) {
            internal::SqlStatement t(db_, path_, "DELETE FROM pattern_tags WHERE pattern_id=?1");
            t.bind(1, id).step();
            internal::SqlStatement d(db_, path_, "DELETE FROM patterns WHERE id=?1");
            d.bind(1, id).step();
        }
        tx.commit();
        return id > 0;
    }

    /// Every stored pattern, by name.
    std::vector<PatternSummary> list() const { return search({}); }

    /// Patterns matching every non-empty field of `q`, by name.
    std::vector<PatternSummary> search(const PatternQuery& q) const {
        using namespace internal;
        std::string sql =
            "SELECT id, name, designer, garment_type, size, pieces, seams, json_bytes, "
            "length(data), updated FROM patterns WHERE 1";
        std::vector<std::string> args;
        auto like = [](const std::string& s) {
            std::string out = "%";
            for (char c : s) {
                if (c == '%' || c == '_' || c == '\\') {
                    out += '\\';
                }
                out += c;
            }
            return out + "%";
        };
        if (!q.name.empty()) {
            args.push_back(like(q.name));
            sql += " AND name LIKE ?" + std::to_string(args.size()) + " ESCAPE '\\'";
        }
        if (!q.designer.empty()) {
            args.push_back(like(q.designer));
            sql += " AND designer LIKE ?" + std::to_string(args.size()) + " ESCAPE '\\'";
        }
        if (!q.garment_type.empty()) {
            args.push_back(q.garment_type);
            sql += " AND garment_type = ?" + std::to_string(args.size());
        }
        if (!q.size.empty()) {
            args.push_back(q.size);
            sql += " AND size = ?" + std::to_string(args.size());
        }
        for (const std::string& t : unique_tags(q.tags)) {
            args.push_back(t);
            sql += " AND id IN (SELECT pattern_id FROM pattern_tags WHERE tag = ?" +
                   std::to_string(args.size()) + ")";
        }
        sql += " ORDER BY name";
        // One read transaction: the rows and their tags come from the same snapshot.
        SqlTransaction tx(db_, path_, "BEGIN");
        SqlStatement st(db_, path_, sql);
        for (std::size_t i = 0; i < args.size(); ++i) {
            st.bind(int(i + 1), args[i]);
        }
        SqlStatement tags(db_, path_,
                          "SELECT tag FROM pattern_tags WHERE pattern_id=?1 ORDER BY tag");
        std::vector<PatternSummary> out;
        while (st.step()) {
            PatternSummary s;
            s.name = st.text(1);
            s.designer = st.text(2);
            s.garment_type = st.text(3);
            s.size = st.text(4);
            s.pieces = std::size_t(st.integer(5));
            s.seams = std::size_t(st.integer(6));
            s.json_bytes = std::size_t(st.integer(7));
            s.stored_bytes = std::size_t(st.integer(8));
            s.updated = st.text(9);
            tags.reset();
            tags.bind(1, st.integer(0));
            while (tags.step()) {
                s.tags.push_back(tags.text(0));
            }
            out.push_back(std::move(s));
        }
        tx.commit();
        return out;
    }

    /// SQLite's PRAGMA integrity_check: "ok" or the problems found, one per line.
    std::string integrity_check() const {
        internal::SqlStatement st(db_, path_, "PRAGMA integrity_check");
        std::string out;
        while (st.step()) {
            out += (out.empty() ? "" : "\n") + st.text(0);
        }
        return out;
    }

    /// The raw connection, for tools and tests that need SQL the class does not offer.
    sqlite3* handle() const { return db_; }

private:
    void require_writable(const std::string& what) const {
        if (options_.read_only) {
            throw InvalidInput(path_ + ": cannot " + what + ": the database was opened read-only");
        }
    }

    std::int64_t row_id(const std::string& name) const {
        internal::SqlStatement st(db_, path_, "SELECT id FROM patterns WHERE name=?1");
        st.bind(1, name);
        return st.step() ? st.integer(0) : 0;
    }

    void open() {
        using namespace internal;
        namespace fs = std::filesystem;
        const bool existed = fs::exists(path_);
        if (!existed && (options_.read_only || !options_.create)) {
            throw InvalidInput(path_ + ": no pattern database here");
        }
        if (!existed) {
            const fs::path parent = fs::path(path_).parent_path();
            std::error_code ec;
            if (!parent.empty()) {
                fs::create_directories(parent, ec);
            }
            if (ec) {
                throw InvalidInput(path_ + ": cannot create directory " + parent.string() + ": " +
                                   ec.message());
            }
        }
        if (options_.read_only) {
            open_read_only();
        } else {
            connect(path_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE);
        }
        try {
            migrate(existed);
        } catch (...) {
            sqlite3_close_v2(db_);
            db_ = nullptr;
            throw;
        }
    }

    void connect(const std::string& name, int flags) {
        using namespace internal;
        if (sqlite3_open_v2(name.c_str(), &db_, flags | SQLITE_OPEN_NOMUTEX, nullptr) !=
            SQLITE_OK) {
            const std::string m = db_ ? sqlite_message(db_) : "out of memory";
            sqlite3_close_v2(db_);
            db_ = nullptr;
            throw InvalidInput(path_ + ": cannot open the pattern database: " + m);
        }
        sqlite3_busy_timeout(db_, options_.busy_timeout_ms);
        sqlite3_extended_result_codes(db_, 0);
    }

    /// `mode=ro` never writes the file; a WAL file also needs its -shm index, which a reader
    /// creates beside the file when absent. Where that is impossible (read-only directory,
    /// another user's file), the file is opened `immutable` and the report says so.
    void open_read_only() {
        std::string uri = "file:";
        for (const char c : path_) {
            if (c == '%' || c == '?' || c == '#' || static_cast<unsigned char>(c) < 0x20) {
                static const char hex[] = "0123456789ABCDEF";
                uri += '%';
                uri += hex[static_cast<unsigned char>(c) >> 4];
                uri += hex[static_cast<unsigned char>(c) & 15];
            } else {
                uri += c;
            }
        }
        const int flags = SQLITE_OPEN_READONLY | SQLITE_OPEN_URI;
        connect(uri + "?mode=ro", flags);
        sqlite3_stmt* probe = nullptr;
        int rc = sqlite3_prepare_v2(db_, "SELECT count(*) FROM sqlite_master", -1, &probe, nullptr);
        if (rc == SQLITE_OK) {
            rc = sqlite3_step(probe);
        }
        sqlite3_finalize(probe);
        if (rc == SQLITE_CANTOPEN || rc == SQLITE_READONLY) {
            sqlite3_close_v2(db_);
            db_ = nullptr;
            connect(uri + "?mode=ro&immutable=1", flags);
            open_report_.immutable = true;
        }
    }

    /// SQLite does not call the busy handler for a change of journal mode, which needs the file
    /// to itself; processes opening a new file at once wait here instead of failing.
    void set_wal_mode() {
        using namespace internal;
        const auto t0 = std::chrono::steady_clock::now();
        for (int attempt = 0;; ++attempt) {
            char* err = nullptr;
            const int rc = sqlite3_exec(db_, "PRAGMA journal_mode=WAL", nullptr, nullptr, &err);
            sqlite3_free(err);
            const double waited_ms =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                    .count();
            if ((rc != SQLITE_BUSY && rc != SQLITE_LOCKED) ||
                waited_ms > options_.busy_timeout_ms) {
                if (rc != SQLITE_OK) {
                    sql_exec(db_, path_, "PRAGMA journal_mode=WAL");  // throws with the message
                }
                return;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(std::min(1 + attempt, 20)));
        }
    }

    void check_identity(int version) const {
        using namespace internal;
        const auto app = std::int32_t(sql_integer(db_, path_, "PRAGMA application_id"));
        if (app != 0 && app != pattern_database_application_id) {
            throw InvalidInput(path_ + ": a SQLite database of another program (application_id " +
                               std::to_string(app) + "), not a Tapeline pattern database");
        }
        if (app == 0 && version == 0 &&
            sql_integer(db_, path_, "SELECT count(*) FROM sqlite_master") > 0) {
            throw InvalidInput(path_ +
                               ": a SQLite database with tables but no Tapeline schema version; "
                               "not a Tapeline pattern database");
        }
        if (version > pattern_database_schema_version) {
            throw InvalidInput(
                path_ + ": the database has schema version " + std::to_string(version) +
                ", newer than this Tapeline (it knows up "
                "to version " +
                std::to_string(pattern_database_schema_version) + "); use a newer Tapeline");
        }
        if (version < 0) {
            throw InvalidInput(path_ + ": invalid schema version " + std::to_string(version));
        }
    }

    void migrate(bool existed) {
        using namespace internal;
        int version = 0;
        {
            // One snapshot: another process creating the schema between two separate reads
            // would show tables without a version. The first read also tells a damaged or
            // foreign file (SQLITE_NOTADB) apart.
            SqlTransaction snapshot(db_, path_, "BEGIN");
            version = int(sql_integer(db_, path_, "PRAGMA user_version"));
            check_identity(version);
            snapshot.commit();
        }
        open_report_.created = !existed;
        open_report_.version_before = version;
        if (options_.read_only) {
            if (version < pattern_database_schema_version) {
                throw InvalidInput(path_ + ": the database has schema version " +
                                   std::to_string(version) + " and needs upgrading to " +
                                   std::to_string(pattern_database_schema_version) +
                                   "; open it writable once");
            }
            open_report_.version_after = version;
            return;
        }
        set_wal_mode();
        sql_exec(
            db_, path_,
            options_.synchronous_full ? "PRAGMA synchronous=FULL" : "PRAGMA synchronous=NORMAL");
        if (version < pattern_database_schema_version) {
            SqlTransaction tx(db_, path_);
            // Another process may have migrated while we waited for the lock.
            version = int(sql_integer(db_, path_, "PRAGMA user_version"));
            check_identity(version);
            for (const DatabaseMigration& m : pattern_database_migrations()) {
                if (m.to_version > version) {
                    m.apply(db_, path_, options_);
                    version = m.to_version;
                }
            }
            sql_exec(db_, path_,
                     "PRAGMA application_id=" + std::to_string(pattern_database_application_id));
            sql_exec(db_, path_, "PRAGMA user_version=" + std::to_string(version));
            tx.commit();
        }
        open_report_.version_after = version;
    }

    std::string path_;
    DatabaseOptions options_;
    sqlite3* db_ = nullptr;
    DatabaseOpenReport open_report_;
};

}  // namespace tapeline::pattern
