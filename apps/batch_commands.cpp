// `tapeline batch JOBS --out RESULTS [--resume] [--retries N]`: every job of a manifest (measure →
// grade → dress) run once, restartably, locally or over MPI ranks (`mpirun -np N tapeline batch
// ...`): rank 0 keeps the results database and hands out jobs one at a time (jobs differ 100× in
// cost), every rank runs jobs (rank 0 in a second thread), each job in a child process of its
// own (a job killed by a signal goes back to the queue), TBB inside each job.
#include "batch_jobs.h"
#include "commands.h"

#include <tapeline/bench/isolation.h>
#include <tapeline/core/errors.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#ifdef TAPELINE_HAVE_MPI
#include <mpi.h>
#endif

#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <set>
#include <string>
#include <thread>
#include <vector>

namespace tapeline::app {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using batch::JobRow;
using batch::JobSpec;

struct BatchArgs {
    std::string jobs, out;
    bool resume = false;
    int retries = 2;
    double job_timeout = 0;  ///< seconds, 0: none
    double job_memory = 0;   ///< GB of address space per job, 0: no limit
};

/// What a worker reports of a job.
struct Result {
    int index = -1;
    bool done = false;
    bool lost = false;  ///< its process was killed by a signal: run it again
    std::string error;
    double seconds = 0;
    std::string outcome;
};

/// Runs job `index` into RESULTS/jobs/<id> in a child process: the files are written into a
/// private folder that is renamed into place when every step is done, so a job's outputs are all
/// there or none. A child killed by a signal (a killed or crashed job, the out-of-memory killer)
/// is `lost`; one past `a.job_timeout` or `a.job_memory`, or whose job threw, has failed.
Result execute(const BatchArgs& a, const std::vector<JobSpec>& jobs, int index, int rank) {
    const JobSpec& job = jobs[std::size_t(index)];
    const auto t0 = std::chrono::steady_clock::now();
    Result r;
    r.index = index;
    const fs::path out = a.out;
    const fs::path final_dir = out / "jobs" / job.id;
    const fs::path tmp =
        out / "jobs" /
        ("." + job.id + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(rank));
    std::string error;
    try {
        fs::remove_all(tmp);
        const bench::ChildOutcome c = bench::run_isolated(
            [&](Json& fields, std::vector<double>&) {
                const Json outcome = batch::run_job(job, tmp.string());
                fs::remove_all(final_dir);  // left by a run killed between rename and record
                fs::rename(tmp, final_dir);
                fields["outcome"] = outcome.dump();
            },
            a.job_timeout, a.job_memory);
        if (c.status == "ok") {
            r.done = true;
            r.outcome = c.fields.value("outcome", std::string());
        } else if (c.status == "timeout") {
            error = "timed out: " + c.message + " (--job-timeout)";
        } else {
            r.lost = c.status == "crash" && c.message.rfind("killed by signal", 0) == 0;
            error = r.lost ? "its process was " + c.message : c.message;
        }
    } catch (const std::exception& e) {
        error = e.what();
    }
    if (!r.done) {
        std::error_code ec;
        fs::remove_all(tmp, ec);
        for (char& c : error) {
            c = (c == '\n' || c == '\r') ? ' ' : c;
        }
        r.error = error;
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return r;
}

/// The coordinator's side: the database, the queue, the progress lines.
class Coordinator {
public:
    Coordinator(const BatchArgs& a, const std::vector<JobSpec>& jobs)
        : args_(a), jobs_(jobs), out_(a.out) {
        fs::create_directories(out_ / "jobs");
        const fs::path db_path = out_ / "batch.sqlite";
        const bool existed = fs::exists(db_path);
        if (existed && !a.resume) {
            throw InvalidInput(a.out +
                               " holds a batch already (batch.sqlite): add --resume to continue "
                               "it, or give another --out");
        }
        db_ = std::make_unique<batch::ResultsDb>(db_path.string(), true);
        std::vector<JobRow> rows = db_->rows();
        if (!existed || rows.empty()) {
            const batch::Transaction transaction(*db_);  // one commit for every job
            for (std::size_t i = 0; i < jobs.size(); ++i) {
                JobRow r;
                r.index = int(i);
                r.id = jobs[i].id;
                r.spec = jobs[i].spec();
                r.status = "pending";
                db_->insert(r);
            }
            rows = db_->rows();
        }
        if (rows.size() != jobs.size()) {
            throw InvalidInput(a.jobs + ": " + std::to_string(jobs.size()) +
                               " jobs, but the batch in " + a.out + " has " +
                               std::to_string(rows.size()) +
                               " (the manifest changed: give another --out)");
        }
        for (std::size_t i = 0; i < rows.size(); ++i) {
            if (rows[i].id != jobs[i].id || rows[i].spec != jobs[i].spec()) {
                throw InvalidInput(a.jobs + ": job '" + jobs[i].id + "' differs from job '" +
                                   rows[i].id + "' of the batch in " + a.out +
                                   " (the manifest changed: give another --out)");
            }
        }
        // Stale private folders of killed runs.
        for (const auto& e : fs::directory_iterator(out_ / "jobs")) {
            const std::string name = e.path().filename().string();
            if (name.size() > 1 && name[0] == '.' && name.find(".tmp.") != std::string::npos) {
                fs::remove_all(e.path());
            }
        }
        for (const JobRow& r : rows) {
            if (r.status == "done") {
                ++skipped_;
                continue;
            }
            if (r.status == "running") {
                db_->set_status(r.index, "pending");  // its run was killed: back to the queue
            }
            if (r.status == "failed" && r.attempts > args_.retries) {
                ++given_up_;
                continue;
            }
            queue_.push_back(r.index);
        }
        total_ = queue_.size();
        for (const JobRow& r : rows) {
            attempts_.push_back(r.attempts);
        }
    }

    bool next(int& index) {
        if (queue_.empty()) {
            return false;
        }
        index = queue_.front();
        queue_.pop_front();
        return true;
    }
    void started(int index, const std::string& host, int rank) {
        const auto t0 = std::chrono::steady_clock::now();
        db_->start(index, host, rank);
        ++attempts_[std::size_t(index)];
        busy_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    void finished(const Result& r, const std::string& host, int rank) {
        const auto t0 = std::chrono::steady_clock::now();
        db_->finish(r.index, r.done, r.error, r.seconds, r.outcome);
        const std::string& id = jobs_[std::size_t(r.index)].id;
        const int attempts = attempts_[std::size_t(r.index)];
        if (r.lost && attempts <= args_.retries) {
            // Killed, not failed: back to the queue in this run (the attempt is counted).
            db_->set_status(r.index, "pending");
            queue_.push_back(r.index);
            busy_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            std::cerr << "tapeline: batch: LOST " << id << " (attempt " << attempts << ", rank "
                      << rank << " on " << host << "): " << r.error << "; back in the queue\n";
            return;
        }
        busy_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        ++finished_;
        failed_ += r.done ? 0 : 1;
        std::cerr << "tapeline: batch: [" << finished_ << "/" << total_ << "] "
                  << (r.done ? "done " : "FAILED ") << id << " (" << std::fixed;
        std::cerr.precision(1);
        std::cerr << r.seconds << " s, rank " << rank << " on " << host << ")"
                  << (r.done ? "" : ": " + r.error) << '\n';
    }
    std::size_t queued() const { return total_; }
    std::size_t skipped() const { return skipped_; }

    /// Time the coordinator spends on a message besides the database (MPI receive and send).
    void add_busy(double seconds) { busy_ += seconds; }

    /// Writes the summary; returns the exit status (0: every job done).
    int close(int ranks) {
        const std::vector<JobRow> rows = db_->rows();
        const double wall =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        const double per_job = finished_ ? 1000 * busy_ / double(finished_) : 0.0;
        batch::write_summary(out_.string(), rows,
                             {{"ranks", ranks},
                              {"jobs_run", finished_},
                              {"wall_seconds", wall},
                              {"coordinator_ms_per_job", per_job}});
        std::size_t done = 0, failed = 0;
        std::string first;
        for (const JobRow& r : rows) {
            done += r.status == "done";
            if (r.status == "failed") {
                ++failed;
                if (first.empty()) {
                    first = r.id + ": " + r.error;
                }
            }
        }
        std::cout << args_.out << ": " << done << " of " << rows.size() << " jobs done";
        if (skipped_) {
            std::cout << " (" << skipped_ << " by an earlier run)";
        }
        if (failed) {
            std::cout << ", " << failed << " failed (first: " << first << ")";
        }
        std::cout << "; summary in " << (out_ / "summary.md").string() << '\n';
        return failed || done != rows.size() ? 1 : 0;
    }

private:
    const BatchArgs& args_;
    const std::vector<JobSpec>& jobs_;
    fs::path out_;
    std::unique_ptr<batch::ResultsDb> db_;
    std::deque<int> queue_;
    std::vector<int> attempts_;  ///< per job, this run's included
    std::size_t total_ = 0, skipped_ = 0, given_up_ = 0, finished_ = 0, failed_ = 0;
    double busy_ = 0;  ///< the coordinator's own work: database updates, messages
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

/// Runs every queued job in this thread, one after the other (rank 0's own jobs).
void run_queue_here(Coordinator& c, const BatchArgs& a, const std::vector<JobSpec>& jobs) {
    const std::string host = batch::host_name();
    int index = 0;
    while (c.next(index)) {
        c.started(index, host, 0);
        c.finished(execute(a, jobs, index, 0), host, 0);
    }
}

int run_local(const BatchArgs& a, const std::vector<JobSpec>& jobs) {
    Coordinator c(a, jobs);
    std::cerr << "tapeline: batch: " << c.queued() << " jobs to run here, one at a time"
              << (c.skipped() ? " (" + std::to_string(c.skipped()) + " done before)" : "") << '\n';
    run_queue_here(c, a, jobs);
    return c.close(1);
}

#ifdef TAPELINE_HAVE_MPI
constexpr int kTagWork = 1;  // worker → coordinator: a request, with the previous job's result
constexpr int kTagJob = 2;   // coordinator → worker: a job index, -1 to stop

/// Whether an MPI launcher (mpirun, srun) started this process.
bool launched_by_mpi() {
    for (const char* v :
         {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "SLURM_STEP_NUM_TASKS"}) {
        if (std::getenv(v)) {
            return true;
        }
    }
    return false;
}

void send_json(const Json& j, int to, int tag) {
    const std::string s = j.dump();
    MPI_Send(s.data(), int(s.size()), MPI_CHAR, to, tag, MPI_COMM_WORLD);
}

Json receive_json(int from, int tag, int* source) {
    // Polled with a short sleep: a blocking probe spins in Open MPI's progress loop and would
    // take a core from the jobs (rank 0 also runs jobs); 2 ms of latency per job is nothing.
    MPI_Status st;
    for (int flag = 0;;) {
        MPI_Iprobe(from, tag, MPI_COMM_WORLD, &flag, &st);
        if (flag) {
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    int n = 0;
    MPI_Get_count(&st, MPI_CHAR, &n);
    std::string s(std::size_t(n), '\0');
    MPI_Recv(s.data(), n, MPI_CHAR, st.MPI_SOURCE, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (source) {
        *source = st.MPI_SOURCE;
    }
    return Json::parse(s);
}

/// A worker: asks for a job, runs it, reports it with the next request, until told to stop.
void worker(const BatchArgs& a, const std::vector<JobSpec>& jobs, int rank) {
    Json request = {{"host", batch::host_name()}};
    for (;;) {
        send_json(request, 0, kTagWork);
        int index = -1;
        MPI_Recv(&index, 1, MPI_INT, 0, kTagJob, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        if (index < 0) {
            return;
        }
        const Result r = execute(a, jobs, index, rank);
        request["result"] = {{"index", r.index}, {"done", r.done},       {"lost", r.lost},
                             {"error", r.error}, {"seconds", r.seconds}, {"outcome", r.outcome}};
    }
}

/// Rank 0's coordinator: answers every worker's request with the next job, records results.
void coordinate(Coordinator& c, int ranks) {
    int active = ranks;
    while (active > 0) {
        int source = 0;
        const Json msg = receive_json(MPI_ANY_SOURCE, kTagWork, &source);
        const std::string host = msg.value("host", std::string("unknown"));
        if (msg.contains("result")) {
            const Json& r = msg["result"];
            Result res;
            res.index = r["index"].get<int>();
            res.done = r["done"].get<bool>();
            res.lost = r["lost"].get<bool>();
            res.error = r["error"].get<std::string>();
            res.seconds = r["seconds"].get<double>();
            res.outcome = r["outcome"].get<std::string>();
            c.finished(res, host, source);
        }
        int index = -1;
        if (c.next(index)) {
            c.started(index, host, source);
        } else {
            --active;
        }
        const auto t0 = std::chrono::steady_clock::now();
        MPI_Send(&index, 1, MPI_INT, source, kTagJob, MPI_COMM_WORLD);
        c.add_busy(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
}

int run_mpi(const BatchArgs& a, const std::vector<JobSpec>& jobs) {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_MULTIPLE, &provided);
    struct Finalize {
        ~Finalize() { MPI_Finalize(); }
    } finalize;
    int rank = 0, ranks = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    // Rank 0 opens the database and decides; every rank learns whether to go on.
    std::unique_ptr<Coordinator> c;
    int ok = 1;
    std::string refusal;
    if (rank == 0) {
        try {
            c = std::make_unique<Coordinator>(a, jobs);
        } catch (const std::exception& e) {
            ok = 0;
            refusal = e.what();
        }
    }
    MPI_Bcast(&ok, 1, MPI_INT, 0, MPI_COMM_WORLD);
    if (!ok) {
        if (rank == 0) {
            throw InvalidInput(refusal);
        }
        return 2;
    }
    if (rank != 0) {
        worker(a, jobs, rank);
        return 0;
    }
    const bool threaded = provided >= MPI_THREAD_MULTIPLE;
    std::cerr << "tapeline: batch: " << c->queued() << " jobs over " << ranks << " MPI ranks"
              << (threaded ? " (rank 0 coordinates and runs jobs)"
                           : " (rank 0 only coordinates: MPI without thread support)")
              << '\n';
    if (threaded) {
        std::thread local([&] { worker(a, jobs, 0); });
        coordinate(*c, ranks);
        local.join();
    } else {
        coordinate(*c, ranks - 1 > 0 ? ranks - 1 : 0);
        if (ranks == 1) {
            run_queue_here(*c, a, jobs);
        }
    }
    return c->close(ranks);
}
#endif

int run_batch(const BatchArgs& a) {
    if (a.retries < 0) {
        throw InvalidInput("--retries must be >= 0");
    }
    if (!(a.job_timeout >= 0) || !(a.job_memory >= 0)) {
        throw InvalidInput("--job-timeout and --job-memory must be >= 0 (0: no limit)");
    }
    const std::vector<JobSpec> jobs = batch::read_manifest(a.jobs);
#ifdef TAPELINE_HAVE_MPI
    if (launched_by_mpi()) {
        return run_mpi(a, jobs);
    }
    std::cerr << "tapeline: batch: not started by an MPI launcher (mpirun, srun): running here\n";
#else
    std::cerr << "tapeline: batch: built without MPI (Debian libopenmpi-dev): running here\n";
#endif
    return run_local(a, jobs);
}

}  // namespace

void register_batch_commands(CLI::App& app) {
    auto a = std::make_shared<BatchArgs>();
    CLI::App* cmd = app.add_subcommand(
        "batch",
        "Run a manifest of jobs (measure, grade, dress per body and pattern), restartably, here "
        "or over MPI ranks (mpirun -np N tapeline batch ...)");
    cmd->add_option("JOBS", a->jobs,
                    "Job manifest: JSON lines, one job per line (body, units, pattern, from, "
                    "fabric, steps, options), or bodies (a glob) × patterns (a list)")
        ->required();
    cmd->add_option("--out", a->out, "Results folder (job outputs, batch.sqlite, summary)")
        ->required();
    cmd->add_flag("--resume", a->resume,
                  "Continue the batch in --out: skip done jobs, retry failed ones");
    cmd->add_option("--retries", a->retries,
                    "Run a job again while it has failed at most this often: a job whose "
                    "process was killed at once, a failed one with --resume")
        ->capture_default_str();
    cmd->add_option("--job-timeout", a->job_timeout,
                    "Seconds after which a job is stopped and has failed (0: no limit)")
        ->capture_default_str();
    cmd->add_option("--job-memory", a->job_memory,
                    "GB of memory per job; beyond it the job has failed (0: no limit)")
        ->capture_default_str();
    cmd->callback([a] {
        const int status = run_batch(*a);
        if (status != 0) {
            std::exit(status);
        }
    });
}

}  // namespace tapeline::app
