// The progress reporter (core/progress.h) through its sink: the rate limit, the closing event,
// silence for short phases and in never mode, and counts that add up when TBB workers advance it.
#include <tapeline/core/progress.h>

#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>
#include <vector>

namespace {

using tapeline::Progress;
using tapeline::ProgressEvent;
using tapeline::ProgressMode;

/// Captures events; restores the process-wide mode and sink afterwards.
class ProgressTest : public ::testing::Test {
protected:
    void SetUp() override {
        tapeline::set_progress_sink([this](const ProgressEvent& e) {
            std::lock_guard<std::mutex> lock(mutex_);
            events_.push_back(e);
        });
    }
    void TearDown() override {
        tapeline::set_progress_sink({});
        tapeline::set_progress_mode(ProgressMode::automatic);
    }
    std::vector<ProgressEvent> events() {
        std::lock_guard<std::mutex> lock(mutex_);
        return events_;
    }

private:
    std::mutex mutex_;
    std::vector<ProgressEvent> events_;
};

TEST_F(ProgressTest, RateLimitedWithOneClosingEvent) {
    {
        Progress p("rate", 100000, 0.0);
        ASSERT_TRUE(p.enabled());
        for (int i = 0; i < 100000; ++i) {
            p.advance();
        }
    }
    const auto e = events();
    // A sink gets one event per 5 s at most: the first update, then the closing one.
    ASSERT_EQ(e.size(), 2u);
    EXPECT_FALSE(e.front().finished);
    EXPECT_EQ(e.front().phase, "rate");
    EXPECT_EQ(e.front().total, 100000u);
    EXPECT_TRUE(e.back().finished);
    EXPECT_EQ(e.back().done, 100000u);
}

TEST_F(ProgressTest, FinishReportsOnceWithTheNote) {
    Progress p("phase", 3, 0.0);
    p.advance();
    p.note("best fit 1.5 mm");
    p.advance(2);
    p.finish();
    p.finish();  // a second finish (and the destructor) adds nothing
    const auto e = events();
    ASSERT_EQ(e.size(), 2u);
    EXPECT_TRUE(e.back().finished);
    EXPECT_EQ(e.back().done, 3u);
    EXPECT_EQ(e.back().note, "best fit 1.5 mm");
    EXPECT_GE(e.back().seconds, e.front().seconds);
}

TEST_F(ProgressTest, ShortPhaseIsSilent) {
    {
        Progress p("short", 10, 60.0);  // ends long before its delay
        for (int i = 0; i < 10; ++i) {
            p.advance();
        }
    }
    EXPECT_TRUE(events().empty());
}

TEST_F(ProgressTest, NeverModeIsSilent) {
    tapeline::set_progress_mode(ProgressMode::never);
    {
        Progress p("quiet", 10, 0.0);
        EXPECT_FALSE(p.enabled());
        p.note("nothing");
        for (int i = 0; i < 10; ++i) {
            p.advance();
        }
    }
    EXPECT_TRUE(events().empty());
}

TEST_F(ProgressTest, AlwaysModeReportsAfterTheDelay) {
    tapeline::set_progress_mode(ProgressMode::always);
    Progress p("delayed", 2, 0.05);
    p.advance();  // before the delay: nothing
    EXPECT_TRUE(events().empty());
    std::this_thread::sleep_for(std::chrono::milliseconds(80));
    p.advance();
    p.finish();
    const auto e = events();
    ASSERT_EQ(e.size(), 2u);
    EXPECT_EQ(e.front().done, 2u);
    EXPECT_GE(e.front().seconds, 0.05);
    EXPECT_TRUE(e.back().finished);
}

TEST_F(ProgressTest, CountsAddUpFromTbbWorkers) {
    const std::size_t n = 200000;
    {
        Progress p("parallel", n, 0.0);
        tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
            p.advance();
            if (i % 1000 == 0) {
                p.note("item " + std::to_string(i));
            }
        });
    }
    const auto e = events();
    ASSERT_GE(e.size(), 1u);
    ASSERT_LE(e.size(), 3u);  // the rate limit holds across threads
    EXPECT_TRUE(e.back().finished);
    EXPECT_EQ(e.back().done, n);
    for (std::size_t k = 0; k + 1 < e.size(); ++k) {
        EXPECT_FALSE(e[k].finished);
        EXPECT_LE(e[k].done, n);
    }
}

}  // namespace

// A cancel request stops work at its next progress point, also inside a TBB loop (the exception
// reaches the caller), and is withdrawn by clear_cancel().
TEST_F(ProgressTest, CancelStopsWorkAtTheNextProgressPoint) {
    tapeline::clear_cancel();
    {
        Progress p("before", 10);
        EXPECT_NO_THROW(p.advance());
        tapeline::request_cancel();
        EXPECT_THROW(p.advance(), tapeline::Cancelled);
        EXPECT_THROW(p.set(5), tapeline::Cancelled);
    }
    std::atomic<std::size_t> done{0};
    {
        Progress p("tbb", 100000);
        EXPECT_THROW(tbb::parallel_for(std::size_t{0}, std::size_t{100000},
                                       [&](std::size_t) {
                                           p.advance();
                                           done.fetch_add(1);
                                       }),
                     tapeline::Cancelled);
    }
    EXPECT_EQ(done.load(), 0u);
    tapeline::clear_cancel();
    Progress p("after", 10);
    EXPECT_NO_THROW(p.advance());
    try {
        tapeline::request_cancel();
        p.advance();
        FAIL() << "no Cancelled";
    } catch (const tapeline::Cancelled& e) {
        EXPECT_STREQ(e.what(), "after: cancelled");
    }
    tapeline::clear_cancel();
}
