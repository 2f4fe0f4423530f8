#ifndef GS_CLI_MESH_IO_H
#define GS_CLI_MESH_IO_H

// Mesh and curve files for the geometric-snake program, with vcglib's importers and
// exporters, read as MeshLab 2020.09 reads them (so the program and the filters see the same
// mesh), and written safely: to a temporary file next to the target, then renamed over it.

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include <common/ml_mesh_type.h>
#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <wrap/io_trimesh/export_obj.h>
#include <wrap/io_trimesh/export_ply.h>
#include <wrap/io_trimesh/import_obj.h>
#include <wrap/io_trimesh/import_off.h>
#include <wrap/io_trimesh/import_ply.h>
#include <wrap/io_trimesh/import_stl.h>

#include <vcg_ext/io/input_file.h>
#include <vcg_ext/io/safe_file_write.h>
#include "mesh_header.h"
#include "obj_faces.h"
#include <vcg_ext/snake/error.h>

namespace gs_cli {

using vcg::tri::SnakeError;

using vcg::tri::ProtectedFile;
using vcg::tri::SafeFileWrite;

inline std::string Extension(const std::string &path) { return SafeFileWrite::Extension(path); }

/// False for a file vcglib's ASCII STL reader would never finish: no line break at all (it skips
/// the first line with getc until '\n') and not the size of a binary STL.
inline bool HasNewlineOrBinaryStlSize(const std::string &path, long long size)
{
    FILE *f = std::fopen(path.c_str(), "rb");
    if (!f) return false;
    unsigned char head[84];
    bool ok = false;
    if (std::fread(head, 1, 84, f) == 84) {
        uint32_t n;
        std::memcpy(&n, head + 80, 4);
        ok = size == 84 + 50LL * n;
    }
    std::rewind(f);
    char buf[65536];
    for (size_t got; !ok && (got = std::fread(buf, 1, sizeof buf, f)) > 0;) ok = std::memchr(buf, '\n', got) != nullptr;
    std::fclose(f);
    return ok;
}

/// A mesh as MeshLab opens it: the vcglib importer of its format, the optional components the
/// file needs, STL vertices unified, normals and bounding box updated (meshlabserver's
/// loadMesh). `mask` receives what the file held (vcg::tri::io::Mask bits).
inline void LoadMesh(const std::string &path, CMeshO &m, int &mask)
{
    namespace io = vcg::tri::io;
    vcg::tri::InputFile::Require(path, "the mesh");
    struct stat st;
    ::stat(path.c_str(), &st);
    if (st.st_size == 0) throw SnakeError("Cannot read the mesh \"" + path + "\": the file is empty.");
    const std::string ext = Extension(path);
    const char *fn = path.c_str();
    if (ext == "stl" && !HasNewlineOrBinaryStlSize(path, st.st_size)) // vcglib's ASCII reader loops forever on it
        throw SnakeError("Cannot read the mesh \"" + path + "\": not a readable STL file.");
    MeshHeader::CheckCounts(path, ext, st.st_size);
    auto enable = [&m](int mk) { // MeshModel::Enable: the optional components the file fills
        if (mk & io::Mask::IOM_VERTTEXCOORD) m.vert.EnableTexCoord();
        if (mk & io::Mask::IOM_WEDGTEXCOORD) m.face.EnableWedgeTexCoord();
        if (mk & io::Mask::IOM_FACECOLOR) m.face.EnableColor();
        if (mk & io::Mask::IOM_FACEQUALITY) m.face.EnableQuality();
        if (mk & io::Mask::IOM_VERTRADIUS) m.vert.EnableRadius();
    };
    auto failed = [&](const char *why) {
        return SnakeError("Cannot read the mesh \"" + path + "\": " + why + ".");
    };
    mask = 0;
    if (ext == "ply") {
        if (!io::ImporterPLY<CMeshO>::LoadMask(fn, mask)) throw failed("not a readable PLY file");
        if (mask & io::Mask::IOM_WEDGCOLOR) mask |= io::Mask::IOM_FACECOLOR;
        enable(mask);
        const int r = io::ImporterPLY<CMeshO>::Open(m, fn, mask);
        if (r != 0 && io::ImporterPLY<CMeshO>::ErrorCritical(r)) throw failed(MeshHeader::PlyError(io::ImporterPLY<CMeshO>::ErrorMsg(r)).c_str());
    } else if (ext == "stl") {
        if (!io::ImporterSTL<CMeshO>::LoadMask(fn, mask)) throw failed("not a readable STL file");
        enable(mask);
        const int r = io::ImporterSTL<CMeshO>::Open(m, fn, mask);
        if (r != 0) throw failed(io::ImporterSTL<CMeshO>::ErrorMsg(r));
        vcg::tri::Clean<CMeshO>::RemoveDuplicateVertex(m); // MeshLab's default "unify STL vertices"
        vcg::tri::Allocator<CMeshO>::CompactEveryVector(m);
    } else if (ext == "obj") {
        ObjFaces faces; // every index checked before the importer sees it (ObjFaces says why)
        faces.Read(path);
        io::ImporterOBJ<CMeshO>::Info oi;
        if (!io::ImporterOBJ<CMeshO>::LoadMask(fn, oi)) throw failed("not a readable OBJ file");
        enable(oi.mask);
        const int r = io::ImporterOBJ<CMeshO>::Open(m, fn, oi);
        if (r != io::ImporterOBJ<CMeshO>::E_NOERROR && !(r & io::ImporterOBJ<CMeshO>::E_NON_CRITICAL_ERROR))
            throw failed(io::ImporterOBJ<CMeshO>::ErrorMsg(r));
        mask = oi.mask;
        if (m.vn != faces.vertices) throw failed("its vertices could not all be read");
        if (m.fn != faces.Triangles()) faces.Rebuild(m, mask); // the importer dropped some
    } else if (ext == "off") {
        if (!io::ImporterOFF<CMeshO>::LoadMask(fn, mask)) throw failed("not a readable OFF file");
        enable(mask);
        const int r = io::ImporterOFF<CMeshO>::Open(m, fn, mask);
        if (r != 0) throw failed(io::ImporterOFF<CMeshO>::ErrorMsg(r));
    } else {
        throw SnakeError("Cannot read the mesh \"" + path + "\": unknown format \"" + ext +
                         "\" (the program reads .ply, .off, .obj and .stl).");
    }
    vcg::tri::UpdateBounding<CMeshO>::Box(m);
    if (m.fn > 0) {
        vcg::tri::UpdateNormal<CMeshO>::PerFaceNormalized(m);
        if (!(mask & io::Mask::IOM_VERTNORMAL)) vcg::tri::UpdateNormal<CMeshO>::PerVertexAngleWeighted(m);
    }
}

/// Checks, before any work, that `path` can be written: extension among `exts`, then
/// SafeFileWrite's checks (folder exists and is writable, not a folder, not one of `keep`).
/// `what` names it in messages.
inline void CheckWritable(const std::string &path, const std::vector<std::string> &exts, const std::string &what,
                          const std::vector<ProtectedFile> &keep)
{
    const std::string ext = Extension(path);
    bool known = false;
    std::string list;
    for (const auto &e : exts) {
        known = known || e == ext;
        list += (list.empty() ? "." : ", .") + e;
    }
    if (!known)
        throw SnakeError("Cannot write " + what + " \"" + path + "\": unknown format \"" + ext + "\" (use " + list +
                         ").");
    SafeFileWrite::CheckTarget(path, keep);
}

/// A vcglib exporter's failure ("Output Stream Error") with the system's reason (errno: disk
/// full, file too large...), which is what the user can act on.
inline SnakeError WriteFailed(const std::string &path, const char *vcgMessage)
{
    const std::string why = errno != 0 ? std::string(std::strerror(errno)) : std::string(vcgMessage);
    return SnakeError("Cannot write \"" + path + "\": " + why + " (" + vcgMessage +
                      "); the existing file, if any, is unchanged.");
}

/// SafeFileWrite for vcglib's exporters, which write to a file name: `writer(tmp)` fills a
/// temporary file in the target's folder (same extension, for writers that choose the format by
/// it), which is flushed to disk and renamed over `path`: a failure leaves no partial file and
/// never truncates an existing one.
inline void AtomicWrite(const std::string &path, const std::function<void(const std::string &)> &writer)
{
    static int counter = 0;
    SafeFileWrite::RemoveLeftovers(path);
    const std::string tmp = SafeFileWrite::TempPrefix(path, long(::getpid())) + std::to_string(++counter) + "." +
                            Extension(path);
    vcg::tri::TempFiles::Add(tmp);
    try {
        errno = 0;
        writer(tmp);
        const int fd = ::open(tmp.c_str(), O_RDONLY);
        const bool synced = fd >= 0 && ::fsync(fd) == 0;
        if (fd >= 0) ::close(fd);
        if (!synced) throw SnakeError("Cannot write \"" + path + "\": " + std::strerror(errno) + ".");
        if (std::rename(tmp.c_str(), SafeFileWrite::Canonical(path).c_str()) != 0)
            throw SnakeError("Cannot write \"" + path + "\": " + std::strerror(errno) + ".");
        vcg::tri::TempFiles::Remove(tmp);
    } catch (...) {
        std::remove(tmp.c_str());
        vcg::tri::TempFiles::Remove(tmp);
        throw;
    }
}

/// The mesh with its vertex quality (and colour) as binary PLY, as meshlabserver saves it
/// with `-m vq vc`.
inline void SaveMeshPly(CMeshO &m, const std::string &path, int mask)
{
    AtomicWrite(path, [&](const std::string &tmp) {
        const int r = vcg::tri::io::ExporterPLY<CMeshO>::Save(m, tmp.c_str(), mask, true);
        if (r != 0)
            throw WriteFailed(path, vcg::tri::io::ExporterPLY<CMeshO>::ErrorMsg(r));
    });
}

/// Polylines as a mesh of vertices and edges (the filters' curve layers), saved by vcglib's
/// PLY (vertex + edge elements) or OBJ (`l` records) exporter.
inline void SavePolylines(const std::vector<std::vector<vcg::Point3d>> &curves, const std::vector<bool> &closed,
                          const std::string &path)
{
    CMeshO pm;
    for (size_t c = 0; c < curves.size(); ++c) {
        const auto &pts = curves[c];
        if (pts.size() < 2) continue;
        const size_t base = pm.vert.size();
        auto vi = vcg::tri::Allocator<CMeshO>::AddVertices(pm, pts.size());
        for (const auto &p : pts) (vi++)->P() = CMeshO::CoordType::Construct(p);
        const size_t n = pts.size(), ne = (closed[c] && n >= 3) ? n : n - 1;
        auto ei = vcg::tri::Allocator<CMeshO>::AddEdges(pm, ne);
        for (size_t i = 0; i < ne; ++i, ++ei) {
            ei->V(0) = &pm.vert[base + i];
            ei->V(1) = &pm.vert[base + (i + 1) % n];
        }
    }
    const std::string ext = Extension(path);
    AtomicWrite(path, [&](const std::string &tmp) {
        namespace io = vcg::tri::io;
        if (ext == "obj") {
            const int r = io::ExporterOBJ<CMeshO>::Save(pm, tmp.c_str(), io::Mask::IOM_EDGEINDEX);
            if (r != 0) throw WriteFailed(path, io::ExporterOBJ<CMeshO>::ErrorMsg(r));
        } else {
            const int r = io::ExporterPLY<CMeshO>::Save(pm, tmp.c_str(), io::Mask::IOM_EDGEINDEX, false);
            if (r != 0) throw WriteFailed(path, io::ExporterPLY<CMeshO>::ErrorMsg(r));
        }
    });
}

} // namespace gs_cli

#endif
