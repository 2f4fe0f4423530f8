#ifndef VCG_EXT_SNAKE_STORED_SESSION_H
#define VCG_EXT_SNAKE_STORED_SESSION_H

// A SnakeSession saved and restored: as JSON (SnakeSessionFile: energy settings, parameters,
// seeds, snakes with pins), to a file written safely, and to the mesh's sidecar
// <mesh>.snakes.json with a throttled autosave (SnakeSidecar, SnakeAutosave). Restoring is all
// or nothing: a file that cannot be used leaves the session unchanged and a SnakeError says why.

#include <ctime>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <vcg_ext/io/safe_file_write.h>
#include <vcg_ext/io/snake_io.h>
#include <vcg_ext/session/session_file.h>
#include <vcg_ext/session/sidecar.h>
#include <vcg_ext/session/snake_session.h>
#include <vcg_ext/snake/error.h>

namespace vcg {
namespace tri {

template <class MeshType>
class SnakeStoredSession : public SnakeSession<MeshType>
{
    typedef SnakeSession<MeshType> Base;

public:
    typedef typename Base::Snake Snake;
    typedef typename Base::Surface Surface;
    typedef SnakeIO<MeshType> IO;
    typedef nlohmann::json json;
    typedef SnakeSessionFile<MeshType> SessionFile;

    explicit SnakeStoredSession(MeshType &m) : Base(m) {}

    /// The whole session (SnakeSessionFile): energy settings, parameters, seeds, snakes with pins.
    json ToJson()
    {
        SessionFile f(this->mesh);
        f.energyFromQuality = this->energy.FromQuality();
        f.energyType = this->energy.Type();
        f.energySmoothing = this->energy.Smoothing();
        f.creaseAngle = this->energy.CreaseAngle();
        f.params = this->params;
        f.seedCost = this->seedCost;
        f.selected = this->selected;
        f.seeds = this->seedList;
        json j = f.HeaderJson(this->mesh);
        for (auto &s : this->snakes) j["snakes"].push_back(IO::ToJson(*s));
        return j;
    }

    /// Restores a session saved by ToJson on this mesh. All or nothing: on error (other
    /// mesh, broken file) the session is unchanged and a SnakeError says why.
    void FromJson(const json &j)
    {
        SessionFile f = SessionFile::Read(this->mesh, j);
        if (this->energy.Apply(f.energyFromQuality, f.energyType, f.energySmoothing, f.creaseAngle)) this->energyChanged();
        const std::shared_ptr<Surface> &surface = this->energy.EnsureSurface();
        this->checkMesh();
        std::vector<std::unique_ptr<Snake>> nsn;
        for (const auto &fs : f.snakes) {
            std::unique_ptr<Snake> s(new Snake(surface, fs.params));
            s->InitFromSamples(fs.samples, fs.closed, fs.lengthScale);
            // the curve a cut embedded, as saved (false, the snake traced anew, if it no longer fits)
            if (!fs.embedded.empty()) s->KeepPolyline(fs.embedded);
            nsn.push_back(std::move(s));
        }
        this->snakes = std::move(nsn);
        this->history.Clear();
        this->selected = f.selected;
        this->params = f.params;
        this->seedList = f.seeds;
        this->seedCost = f.seedCost;
        this->touch("load");
    }

    /// Writes the session safely (SafeFileWrite: temporary file, then rename): a crash or a
    /// full disk never leaves a half-written session behind.
    void Save(const std::string &path)
    {
        if (path.empty()) throw SnakeError("Geometric snake: no file name to save the session to.");
        SafeFileWrite::Write(path, ToJson().dump(1) + "\n");
        autosave.Saved(this->revision);
    }

    /// Loads a session file; false if there is none, throws if it is unusable. Only what the
    /// session needs is kept while reading (SnakeIO::ParseLean): memory about the file's size.
    bool Load(const std::string &path)
    {
        std::error_code ec;
        if (!std::filesystem::exists(path, ec)) return false;
        FromJson(IO::ParseFileLean(path));
        autosave.Saved(this->revision);
        return true;
    }

    typedef SnakeAutosave::Status SidecarStatus;
    /// Starts the session of the mesh file `meshPath`: restores its sidecar (if `restore` and it
    /// exists) and autosaves to it from now on. A sidecar that cannot be read (broken, truncated,
    /// made on another mesh, too large) is never touched: the session autosaves to a new
    /// SnakeSidecar::RecoveryPath() file instead, and the message says so (SnakeAutosave::Open).
    /// That holds too when the session came from the mesh (`restore` false): a sidecar of the mesh
    /// as it is on disk is not this mesh's once a cut added faces (issue 34), and keeps its curves.
    SidecarStatus OpenSidecar(const std::string &meshPath, bool restore, std::time_t now = std::time(nullptr))
    {
        return autosave.Open(meshPath, restore, now, [this](const std::string &side, bool load) {
            if (load)
                Load(side);
            else
                SessionFile::Read(this->mesh, IO::ParseFileLean(side)); // readable, and of this mesh?
        });
    }

    /// Autosave target (empty: none) and minimum interval between two autosaves.
    void SetAutosave(const std::string &path, double minIntervalSeconds = 1.0) { autosave.Set(path, minIntervalSeconds); }
    const std::string &AutosavePath() const { return autosave.Path(); }
    /// Saves if something changed since the last save and (unless forced) the interval
    /// has passed. Returns true if it wrote. Throws SnakeError if writing fails.
    bool Autosave(bool force = false)
    {
        if (!autosave.Due(this->revision, force)) return false;
        Save(autosave.Path());
        return true;
    }
    bool Dirty() const { return autosave.Dirty(this->revision); }

private:
    SnakeAutosave autosave;
};

} // namespace tri
} // namespace vcg

#endif
