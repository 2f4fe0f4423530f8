#ifndef VCG_EXT_SNAKE_SIDECAR_H
#define VCG_EXT_SNAKE_SIDECAR_H

// Where a mesh's snake session lives: the sidecar file "<mesh file>.snakes.json" next to the
// mesh, the recovery file a session goes to when the sidecar could not be read (the user's file
// is then kept exactly as it was, issue 8), the files no export or autosave may replace, and
// when the session is saved there (SnakeAutosave).

#include <chrono>
#include <ctime>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include <vcg_ext/io/safe_file_write.h>

namespace vcg {
namespace tri {

struct SnakeSidecar
{
    /// "<mesh file>.snakes.json" ("" for a mesh without a file).
    static std::string Path(const std::string &meshPath)
    {
        if (meshPath.empty()) return std::string();
        return meshPath + ".snakes.json";
    }

    /// "<mesh>.snakes.recovered-<YYYYMMDD-HHMMSS>[-k].json", a name not yet taken.
    static std::string RecoveryPath(const std::string &meshPath, std::time_t when)
    {
        char stamp[32];
        std::tm tmv;
        localtime_r(&when, &tmv);
        std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &tmv);
        std::error_code ec;
        for (int k = 1;; ++k) {
            std::string p = meshPath + ".snakes.recovered-" + stamp + (k > 1 ? "-" + std::to_string(k) : "") + ".json";
            if (!std::filesystem::exists(p, ec)) return p;
        }
    }

    /// Files of a mesh that curve exports, autosaves and the geometric-snake program never
    /// overwrite: the mesh itself, its sidecar, the sidecar's backup and its recovery files.
    /// The one rule of the filters, the edit tool and the program. `label`: the mesh's name for
    /// messages (default: path).
    static std::vector<ProtectedFile> ProtectedFiles(const std::string &meshPath, const std::string &label = "")
    {
        if (meshPath.empty()) return {};
        const std::string name = label.empty() ? meshPath : label;
        std::vector<ProtectedFile> keep{
            {meshPath, "the mesh \"" + name + "\""},
            {Path(meshPath), "the snake session file (sidecar) of \"" + name + "\""},
            {Path(meshPath) + ".bak", "a backup of the snake session file of \"" + name + "\""}};
        namespace fs = std::filesystem;
        std::error_code ec;
        const fs::path mp = fs::absolute(meshPath, ec);
        const std::string prefix = mp.filename().string() + ".snakes.recovered-";
        for (fs::directory_iterator it(mp.parent_path(), ec), end; !ec && it != end; it.increment(ec))
            if (it->path().filename().string().compare(0, prefix.size(), prefix) == 0)
                keep.push_back({it->path().string(), "a recovered snake session of \"" + name + "\""});
        return keep;
    }
};

/// Where and when a session is saved: the target (the sidecar, or a recovery file), throttled
/// to one save per interval, and only when the session changed (its revision) since the last.
class SnakeAutosave
{
public:
    /// What Open did, for the status line and the Log.
    struct Status
    {
        bool restored = false;   ///< the session was restored from the sidecar
        bool unreadable = false; ///< a sidecar exists but could not be used: it is kept untouched
        std::string message;     ///< for the user ("" when there is nothing to say)
    };

    /// Starts saving the session of the mesh file `meshPath` to its sidecar. If the sidecar
    /// exists, `read(path, restore)` restores the session from it (`restore`) or only checks it
    /// is readable; a sidecar it throws on is never touched: the session is saved to a new
    /// RecoveryPath() file instead, and the message says so.
    template <class Read>
    Status Open(const std::string &meshPath, bool restore, std::time_t now, Read read)
    {
        Status st;
        Set(std::string());
        if (meshPath.empty()) return st;
        const std::string side = SnakeSidecar::Path(meshPath);
        std::error_code ec;
        if (std::filesystem::exists(side, ec)) {
            try {
                read(side, restore);
                if (restore) {
                    st.restored = true;
                    st.message = "Restored " + side + ".";
                }
            } catch (const std::exception &e) {
                st.unreadable = true;
                const std::string rec = SnakeSidecar::RecoveryPath(meshPath, now);
                st.message = std::string(e.what()) + " The file is kept unchanged; this session is saved to " + rec + ".";
                Set(rec, 1.0);
                return st;
            }
        }
        Set(side, 1.0);
        return st;
    }

    /// The target (empty: none) and the minimum interval between two saves.
    void Set(const std::string &p, double minIntervalSeconds = 1.0)
    {
        target = p;
        interval = minIntervalSeconds;
    }
    const std::string &Path() const { return target; }
    /// Whether a save of the session at `revision` is due now (`force`: whatever the interval);
    /// if so, the interval starts again.
    bool Due(long revision, bool force)
    {
        if (target.empty() || revision == savedRevision) return false;
        const auto now = std::chrono::steady_clock::now();
        if (!force && last.time_since_epoch().count() != 0 && std::chrono::duration<double>(now - last).count() < interval)
            return false;
        last = now;
        return true;
    }
    /// The session at `revision` is in a file (saved or loaded).
    void Saved(long revision) { savedRevision = revision; }
    bool Dirty(long revision) const { return revision != savedRevision; }

private:
    std::string target;
    double interval = 1.0;
    std::chrono::steady_clock::time_point last;
    long savedRevision = 0;
};

} // namespace tri
} // namespace vcg

#endif
