// Variational Shape Approximation for vcglib — progress reports from deep inside long passes,
// a few times a second, through vcg's callback.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VSA_PROGRESS_H
#define VSA_PROGRESS_H

#include <cstring>  // before vcglib 2020.09's wrap/callback.h, which uses strcpy without it

#include <wrap/callback.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <vector>

namespace vcg {
namespace tri {
namespace vsa {

/// Seconds between two reports of a stage: the bar moves several times a second, and a report
/// (MeshLab repaints its window) stays rare beside the work.
constexpr double kProgressSeconds = 0.2;
/// Items of work (faces, patches, half-edges) between two looks at the clock: microseconds of
/// work, beside which reading the clock costs nothing.
constexpr int kProgressItems = 4096;

namespace detail {
/// kProgressSeconds, or what tests set (0: report at every look at the clock).
inline double &ProgressSeconds()
{
    static double seconds = kProgressSeconds;
    return seconds;
}
}  // namespace detail

/// One stage of the pipeline (setup, seeding, Lloyd iterations) reporting its progress through
/// `cb` with `text`. While it lives it is the current stage of its thread: the library's loops
/// run on that thread tell it the work they did (ProgressTick), and it calls `cb` when
/// detail::ProgressSeconds() have passed since its last call, with a position (0..100) that
/// never decreases. Step() says which positions the work ahead spans. A stage without a callback
/// does nothing and leaves the current stage as it was. The callback's return value is ignored
/// (nothing in the library cancels).
class ProgressStage
{
public:
    /// Reports nothing yet: a mesh refused at once never moves the bar.
    ProgressStage(CallBackPos *cb, const char *text)
        : cb_(cb), text_(text), outer_(Current()), last_(std::chrono::steady_clock::now())
    {
        if (cb_) Current() = this;
    }
    ~ProgressStage()
    {
        if (cb_) Current() = outer_;
    }
    ProgressStage(const ProgressStage &) = delete;
    ProgressStage &operator=(const ProgressStage &) = delete;

    /// The work from here to the next Step takes the position from `from` to `to` in about
    /// `items` items of work (ProgressTick); it stops at `to` when there is more. A `text` says
    /// what the stage does from here on.
    void Step(double from, double to, double items, const char *text = nullptr)
    {
        if (text) text_ = text;
        from_ = std::max(from, position_);
        to_ = std::max(to, from_);
        items_ = std::max(items, 1.0);
        done_ = 0;
        Advance(0);
    }

    /// `items` more items of work done; looks at the clock once kProgressItems have gathered,
    /// and reports when one is due.
    void Advance(double items)
    {
        if (!cb_) return;
        Defer(items);
        if (pending_ < kProgressItems) return;
        pending_ = 0;
        const auto now = std::chrono::steady_clock::now();
        if (std::chrono::duration<double>(now - last_).count() >= detail::ProgressSeconds()) Report(now);
    }

    /// `items` more items of work done, counted without looking at the clock.
    void Defer(double items)
    {
        done_ += items;
        pending_ += items;
    }

    /// The stage is over: reports 100 (with `text`, if given), and the stage that was current
    /// before it is again.
    void Done(const char *text = nullptr)
    {
        if (!cb_) return;
        if (text) text_ = text;
        from_ = to_ = 100;
        Report(std::chrono::steady_clock::now());
        Current() = outer_;
        cb_ = nullptr;
    }

    /// The current stage of the calling thread, or null.
    static ProgressStage *&Current()
    {
        static thread_local ProgressStage *current = nullptr;
        return current;
    }

private:
    void Report(std::chrono::steady_clock::time_point now)
    {
        position_ = std::max(position_, from_ + (to_ - from_) * std::min(1.0, done_ / items_));
        last_ = now;
        cb_(int(position_), text_);
    }

    CallBackPos *cb_;
    const char *text_;
    ProgressStage *outer_;
    std::chrono::steady_clock::time_point last_;  ///< of the last report, or of the start
    double position_ = 0, from_ = 0, to_ = 0, items_ = 1, done_ = 0, pending_ = 0;
};

/// Tells the calling thread's current stage, if any, that `items` more items of work were done.
/// Within a parallel pass only the calling thread (OpenMP's thread 0) calls it, so the callback
/// never runs on two threads.
inline void ProgressTick(double items)
{
    if (ProgressStage *stage = ProgressStage::Current()) stage->Advance(items);
}

/// Resizes `v` to `n` items a kProgressItems at a time, each a tick: value-initialising (and
/// first touching) the memory of millions of items takes long enough to report on.
template <class T>
void ResizeReporting(std::vector<T> &v, size_t n)
{
    v.reserve(n);
    for (size_t size = v.size(); size < n;) {
        const size_t grown = std::min(n, size + size_t(kProgressItems));
        v.resize(grown);
        ProgressTick(double(grown - size));
        size = grown;
    }
    v.resize(n);
}

/// Counts a sequential loop's items and passes them on to ProgressTick every kProgressItems, and
/// what is left when it goes, so that many short loops (a region's insertion, its local flood)
/// add up: `ProgressCounter progress; for (...) { ...; progress.Count(); }`.
class ProgressCounter
{
public:
    ProgressCounter() = default;
    ProgressCounter(const ProgressCounter &) = delete;
    ProgressCounter &operator=(const ProgressCounter &) = delete;
    ~ProgressCounter()
    {
        if (count_ == 0) return;
        if (ProgressStage *stage = ProgressStage::Current()) stage->Defer(count_);  // no callback from here
    }

    void Count(int items = 1)
    {
        count_ += items;
        if (count_ >= kProgressItems) {
            ProgressTick(count_);
            count_ = 0;
        }
    }

private:
    int count_ = 0;
};

}  // namespace vsa
}  // namespace tri
}  // namespace vcg

#endif  // VSA_PROGRESS_H
