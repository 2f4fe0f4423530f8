#ifndef VCG_EXT_SNAKE_STOP_H
#define VCG_EXT_SNAKE_STOP_H

// Why a run of snake operations ended (issue 33: every Run ends by itself and says why). The
// engine decides it in one place -- SnakeRunLimits::Check after every operation -- and every host
// (the edit tool's Run, the filters, the `geometric-snake` program) shows the same reason and
// message: the status line, MeshLab's Log, the JSON `stop` field and `warnings`, stderr.

#include <cmath>
#include <cstdio>
#include <string>

#include <vcg_ext/snake/error.h>

namespace vcg {
namespace tri {

/// The end of a run. `Running`: not ended (or not run yet).
enum class SnakeStop {
    Running = 0,
    Converged,     ///< the curve stopped moving (SnakeRunControl's convergence test)
    Collapsed,     ///< a closed snake shrinking where no feature holds it (to a point or a stub)
    LeftPart,      ///< a closed snake sliding away from the part it was seeded around
    MaxOperations, ///< the operation limit of the run reached before convergence
    TimeLimit,     ///< the time limit of the run reached before convergence
    Cancelled      ///< stopped by the user (Stop, Esc) or the caller's progress callback
};

/// The JSON and command-line word of a reason.
inline const char *SnakeStopKey(SnakeStop s)
{
    switch (s) {
    case SnakeStop::Converged: return "converged";
    case SnakeStop::Collapsed: return "collapsed";
    case SnakeStop::LeftPart: return "left_part";
    case SnakeStop::MaxOperations: return "max_operations";
    case SnakeStop::TimeLimit: return "time_limit";
    case SnakeStop::Cancelled: return "cancelled";
    default: return "running";
    }
}

/// A few words for a host's summary line ("... 40 operations, <summary>, ..."); the full
/// message is SnakeStats::stopMessage.
inline const char *SnakeStopSummary(SnakeStop s)
{
    switch (s) {
    case SnakeStop::Converged: return "converged";
    case SnakeStop::Collapsed: return "STOPPED: the closed snake collapses (see the warning)";
    case SnakeStop::LeftPart: return "STOPPED: the closed snake left its part (see the warning)";
    case SnakeStop::MaxOperations: return "NOT converged: Max operations reached";
    case SnakeStop::TimeLimit: return "NOT converged: time limit reached";
    case SnakeStop::Cancelled: return "cancelled";
    default: return "running";
    }
}

/// The run ended without the snake settling on a feature: the hosts show it as a warning (red in
/// the status line). A user's Stop is not one.
inline bool SnakeStopIsProblem(SnakeStop s)
{
    return s == SnakeStop::Collapsed || s == SnakeStop::LeftPart || s == SnakeStop::MaxOperations ||
           s == SnakeStop::TimeLimit;
}

/// The limits of one run (Run in the edit tool, a filter call, a program run): the operation
/// count and the wall time, both counted from the run's start.
struct SnakeRunLimits
{
    int maxOperations = 500;
    double seconds = 0; ///< 0: no time limit

    void Validate() const
    {
        if (maxOperations < 0 || maxOperations > 10000000)
            throw SnakeError("Geometric snake: Max operations must be in [0, 10000000].");
        if (!std::isfinite(seconds) || seconds < 0 || seconds > 1e6)
            throw SnakeError("Geometric snake: the time limit must be in [0, 1e6] seconds (0: none).");
    }

    /// Why the run ends after `ops` operations and `elapsed` seconds, given the engine's verdict
    /// on the last operation (SnakeStats::stop: Running, Converged, Collapsed or LeftPart), or
    /// Running if it goes on. The engine's verdict wins over a limit reached at the same time.
    SnakeStop Check(SnakeStop engine, int ops, double elapsed) const
    {
        if (engine == SnakeStop::Converged || engine == SnakeStop::Collapsed || engine == SnakeStop::LeftPart)
            return engine; // a limit or a cancel of an earlier run does not end this one
        if (ops >= maxOperations) return SnakeStop::MaxOperations;
        if (seconds > 0 && ops > 0 && elapsed >= seconds) return SnakeStop::TimeLimit; // one operation at least
        return SnakeStop::Running;
    }

    /// The message of a limit reached (MaxOperations, TimeLimit), else empty: the engine's own
    /// reasons carry their message (SnakeStats::stopMessage).
    std::string Message(SnakeStop s, int ops, double elapsed) const
    {
        char msg[300];
        if (s == SnakeStop::MaxOperations)
            std::snprintf(msg, sizeof msg,
                          "Max operations (%d) reached after %.1f s before the snake converged: Run again to go on, or "
                          "raise Max operations.", maxOperations, elapsed);
        else if (s == SnakeStop::TimeLimit)
            std::snprintf(msg, sizeof msg,
                          "the time limit (%g s) was reached after %d operations before the snake converged: Run "
                          "again to go on, or raise the time limit.", seconds, ops);
        else
            return std::string();
        return msg;
    }
};

} // namespace tri
} // namespace vcg

#endif
