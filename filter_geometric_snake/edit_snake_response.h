#ifndef EDIT_SNAKE_RESPONSE_H
#define EDIT_SNAKE_RESPONSE_H

// How long the user waits (issue 37): from an input (a seed click, Enter) to the first redraw
// that shows its result, split into the tool's own work and MeshLab's redraw of the mesh
// (on a 1.2M-face mesh under software OpenGL the redraw is most of it). The edit tool starts
// the clock when it handles the input and stops it in its decoration, which MeshLab draws
// after the mesh, or where the tool draws the change itself; one Log line per input, which the
// GUI test reads.

#include <chrono>
#include <cstdio>
#include <string>

class SnakeResponseClock
{
public:
    typedef std::chrono::steady_clock Clock;

    /// The input `what` arrives (e.g. "seed", "build").
    void Start(const char *what)
    {
        label = what;
        t0 = Clock::now();
        handled = t0;
        pending = true;
    }
    /// The tool's handling of it ended; the redraw comes next.
    void Handled()
    {
        if (pending) handled = Clock::now();
    }
    void Cancel() { pending = false; }
    bool Pending() const { return pending; }
    /// Called when the decoration is drawn: the line for the Log once the input is shown
    /// ("" if no input is waiting); `how`: "redraw" (MeshLab's, of the whole scene) or "drawn
    /// over the last frame" (the tool's own, edit_snake_quick_draw.cpp).
    std::string Shown(const char *how)
    {
        if (!pending) return std::string();
        pending = false;
        const Clock::time_point now = Clock::now();
        char buf[200];
        std::snprintf(buf, sizeof buf, "Geometric snake: %s shown %.0f ms after the input (tool %.0f ms, %s %.0f ms)",
                      label.c_str(), ms(t0, now), ms(t0, handled), how, ms(handled, now));
        return buf;
    }

private:
    std::string label;
    Clock::time_point t0, handled;
    bool pending = false;
    static double ms(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); }
};

#endif
