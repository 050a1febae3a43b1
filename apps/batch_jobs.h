// `tapeline batch`: the jobs of a batch (a JSON-lines manifest), how one job runs (measure →
// grade → dress, its files written into a directory that is renamed into place when every step
// is done) and the SQLite results database that makes a batch restartable. The distribution over
// MPI ranks is in batch_commands.cpp.
#pragma once

#include <nlohmann/json.hpp>

#include <sqlite3.h>

#include <exception>
#include <string>
#include <vector>

namespace tapeline::app::batch {

/// One job of the manifest.
struct JobSpec {
    std::string id;  ///< stable name: its directory under RESULTS/jobs
    std::string body, units, up, front, pose;
    std::string pattern, db;     ///< pattern file, or a name in the pattern database `db`
    std::string from, from_set;  ///< the measurement set the pattern was drafted for (grading)
    std::string fabric;
    std::vector<std::string> steps;  ///< in order: measure, grade, dress
    nlohmann::json options;          ///< checked keys (see kOptionKeys in batch_jobs.cpp)
    /// The job as canonical JSON (what --resume compares with the database).
    std::string spec() const;
};

/// The jobs of a manifest: one JSON object per line (blank lines and lines starting with # are
/// skipped); a line with `bodies` (a glob) and/or `patterns` (a list) stands for their
/// cross-product. Relative paths are relative to the manifest's folder. InvalidInput naming the
/// file and line: not JSON, an unknown or missing key, a key of the wrong type, an unknown step,
/// grading without `from`, a glob that matches nothing.
std::vector<JobSpec> read_manifest(const std::string& path);

/// Runs one job, writing its files into `dir` (created): measure.json (as `tapeline measure`),
/// graded.json and grade.json (the graded pattern and the grading report), dressed.obj and
/// dress.json (as `tapeline dress --out --report`). Returns what the summary shows of it
/// (measurements, drape gates). Throws as the steps do.
nlohmann::json run_job(const JobSpec& job, const std::string& dir);

/// A job's row in the results database.
struct JobRow {
    int index = 0;
    std::string id, spec, status, error, host, outcome;
    int attempts = 0, rank = -1;
    double started = 0, finished = 0, seconds = 0;
};

/// The results database (RESULTS/batch.sqlite): one row per job with its status (pending,
/// running, done, failed), attempts, error line, host and rank, times and outcome. Only the
/// coordinating process writes it.
class ResultsDb {
public:
    ResultsDb(const std::string& path, bool create);
    ~ResultsDb();
    ResultsDb(const ResultsDb&) = delete;
    ResultsDb& operator=(const ResultsDb&) = delete;

    std::vector<JobRow> rows();
    void insert(const JobRow& row);
    void start(int index, const std::string& host, int rank);
    void finish(int index, bool done, const std::string& error, double seconds,
                const std::string& outcome);
    void set_status(int index, const std::string& status);
    /// Runs one SQL statement without results (BEGIN, COMMIT, ...).
    void exec(const std::string& sql);

private:
    sqlite3* db_ = nullptr;
    std::string path_;
};

/// A transaction on the results database: committed at the end of its scope, rolled back when
/// the scope is left by an exception.
class Transaction {
public:
    explicit Transaction(ResultsDb& db) : db_(db) { db_.exec("BEGIN"); }
    ~Transaction() {
        try {
            db_.exec(std::uncaught_exceptions() > count_ ? "ROLLBACK" : "COMMIT");
        } catch (...) {
        }
    }
    Transaction(const Transaction&) = delete;
    Transaction& operator=(const Transaction&) = delete;

private:
    ResultsDb& db_;
    int count_ = std::uncaught_exceptions();
};

/// Seconds since the epoch (database times).
double now_seconds();
/// This machine's host name.
std::string host_name();

/// summary.json, summary.md and contact_sheet.png of a batch from its database rows (written
/// atomically); `run` (ranks, wall time, the coordinator's time per job) goes into the summary.
void write_summary(const std::string& out_dir, const std::vector<JobRow>& rows,
                   const nlohmann::json& run);

}  // namespace tapeline::app::batch
