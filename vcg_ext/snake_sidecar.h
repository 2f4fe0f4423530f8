#ifndef VCG_EXT_SNAKE_SIDECAR_H
#define VCG_EXT_SNAKE_SIDECAR_H

// Where a mesh's snake session lives: the sidecar file "<mesh file>.snakes.json" next to the
// mesh, the recovery file a session goes to when the sidecar could not be read (the user's file
// is then kept exactly as it was, issue 8), and the files no export or autosave may replace.

#include <ctime>
#include <filesystem>
#include <string>
#include <vector>

#include <vcg_ext/safe_file_write.h>

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

    /// Files of a mesh that curve exports and autosaves never overwrite: the mesh itself, its
    /// sidecar and the sidecar's backup. `label`: the mesh's name for messages (default: path).
    static std::vector<ProtectedFile> ProtectedFiles(const std::string &meshPath, const std::string &label = "")
    {
        if (meshPath.empty()) return {};
        const std::string name = label.empty() ? meshPath : label;
        return {{meshPath, "the mesh \"" + name + "\""},
                {Path(meshPath), "the snake session file (sidecar) of \"" + name + "\""},
                {Path(meshPath) + ".bak", "a backup of the snake session file of \"" + name + "\""}};
    }
};

} // namespace tri
} // namespace vcg

#endif
