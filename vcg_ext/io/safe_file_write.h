#ifndef VCG_EXT_SAFE_FILE_WRITE_H
#define VCG_EXT_SAFE_FILE_WRITE_H

// Writes that never lose the user's data: the target is checked first (folder, not a folder
// itself, not a file the user must keep), the content goes to a temporary file in the same
// folder, is flushed to disk, and only then renamed over the target. rename() within one file
// system is atomic on POSIX: the target is always either the old file or the complete new one.
// Temporary files are named "<dir>/.<name>.gs-tmp-<pid>-<random>" and listed in TempFiles while
// they exist: a program's signal handler removes them (TempFiles::RemoveAll), and a later write
// to the same target removes those a killed process left (RemoveLeftovers).

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <vcg_ext/snake/error.h>

namespace vcg {
namespace tri {

/// A file a write must never replace, and what it is, for the message
/// (e.g. {"/data/part.ply", "the mesh being worked on"}).
struct ProtectedFile
{
    std::string path;
    std::string what;
};

/// The temporary files this process is writing, removable from a signal handler.
class TempFiles
{
public:
    static void Add(const std::string &path)
    {
        for (auto &s : Slots())
            if (s[0] == '\0' && path.size() < sizeof s) {
                std::memcpy(s, path.c_str(), path.size() + 1);
                return;
            }
    }
    static void Remove(const std::string &path)
    {
        for (auto &s : Slots())
            if (path == s) s[0] = '\0';
    }
    /// Unlinks every listed file; async-signal-safe (for SIGINT, SIGTERM, SIGHUP, SIGXFSZ, SIGALRM).
    static void RemoveAll()
    {
        for (auto &s : Slots())
            if (s[0] != '\0') {
                ::unlink(s);
                s[0] = '\0';
            }
    }

private:
    static char (&Slots())[16][4096]
    {
        static char names[16][4096];
        return names;
    }
};

class SafeFileWrite
{
public:
    /// "<dir>/.<name>.gs-tmp-<pid>-": every temporary file of a write to `target` by process pid
    /// starts so (in the folder of `target`, which is written through a symbolic link).
    static std::string TempPrefix(const std::string &target, long pid)
    {
        const std::filesystem::path t(Canonical(target));
        return t.parent_path().string() + "/." + t.filename().string() + ".gs-tmp-" + std::to_string(pid) + "-";
    }

    /// Removes the temporary files of writes to `target` whose process has ended (killed before it
    /// could clean up).
    static void RemoveLeftovers(const std::string &target)
    {
        const std::string prefix = TempPrefix(target, 0);
        const size_t slash = prefix.find_last_of('/');
        const std::string dir = prefix.substr(0, slash), stem = prefix.substr(slash + 1, prefix.size() - slash - 3);
        DIR *d = ::opendir(dir.c_str());
        if (!d) return;
        while (dirent *e = ::readdir(d)) {
            if (std::strncmp(e->d_name, stem.c_str(), stem.size()) != 0) continue;
            const long pid = std::strtol(e->d_name + stem.size(), nullptr, 10);
            if (pid > 0 && pid != long(::getpid()) && ::kill(pid_t(pid), 0) != 0 && errno == ESRCH)
                ::unlink((dir + "/" + e->d_name).c_str());
        }
        ::closedir(d);
    }

    /// Lower-case extension without the dot, "" when the file name has none ("a.b/c" -> "").
    static std::string Extension(const std::string &path)
    {
        std::string e = std::filesystem::path(path).extension().string();
        if (!e.empty() && e[0] == '.') e.erase(0, 1);
        for (auto &c : e) c = char(std::tolower(static_cast<unsigned char>(c)));
        return e;
    }

    /// True when a and b name the same file (hard links and different spellings included), or
    /// the same place when it does not exist yet.
    static bool SameFile(const std::string &a, const std::string &b)
    {
        if (a.empty() || b.empty()) return false;
        std::error_code ec;
        if (std::filesystem::exists(a, ec) && std::filesystem::exists(b, ec)) {
            bool same = std::filesystem::equivalent(a, b, ec);
            if (!ec) return same;
        }
        return Canonical(a) == Canonical(b);
    }

    /// Absolute path with symbolic links resolved as far as the path exists.
    static std::string Canonical(const std::string &p)
    {
        std::error_code ec;
        std::filesystem::path c = std::filesystem::weakly_canonical(std::filesystem::absolute(p, ec), ec);
        return ec ? p : c.string();
    }

    /// Refuses, with a message for the user, a target that cannot be written safely.
    static void CheckTarget(const std::string &path, const std::vector<ProtectedFile> &keep = {})
    {
        namespace fs = std::filesystem;
        if (path.empty()) throw SnakeError("No output file name given.");
        for (const auto &k : keep)
            if (SameFile(path, k.path))
                throw SnakeError("Refusing to write \"" + path + "\": it is " + k.what +
                                 ", which is never overwritten. Choose another file name.");
        std::error_code ec;
        const fs::path target = Canonical(path);
        if (fs::is_directory(target, ec)) throw SnakeError("Cannot write \"" + path + "\": it is a folder.");
        if (fs::exists(target, ec) && !fs::is_regular_file(target, ec))
            throw SnakeError("Cannot write \"" + path + "\": it is not a regular file.");
        const fs::path dir = target.parent_path();
        if (!fs::is_directory(dir, ec)) throw SnakeError("Cannot write \"" + path + "\": the folder does not exist.");
        if (::access(dir.c_str(), W_OK | X_OK) != 0)
            throw SnakeError("Cannot write \"" + path + "\": the folder is not writable.");
    }

    /// Replaces (or creates) `path` with exactly `content`, atomically; throws SnakeError and
    /// leaves any existing file untouched on failure.
    static void Write(const std::string &path, const std::string &content, const std::vector<ProtectedFile> &keep = {})
    {
        CheckTarget(path, keep);
        const std::string target = Canonical(path); // through a symbolic link: keep the link
        RemoveLeftovers(target);
        std::string tmpl = TempPrefix(target, long(::getpid())) + "XXXXXX";
        std::vector<char> name(tmpl.begin(), tmpl.end());
        name.push_back('\0');
        const int fd = ::mkstemp(name.data());
        if (fd < 0) throw SnakeError("Cannot write \"" + path + "\": " + std::strerror(errno) + ".");
        const std::string tmp(name.data());
        TempFiles::Add(tmp);
        auto fail = [&](const std::string &why) {
            ::close(fd);
            std::remove(tmp.c_str());
            TempFiles::Remove(tmp);
            throw SnakeError("Cannot write \"" + path + "\": " + why + ". The existing file, if any, is unchanged.");
        };
        // the new file gets the old file's permissions, or the usual ones for a new file
        struct stat old;
        mode_t mode;
        if (::stat(target.c_str(), &old) == 0) mode = old.st_mode & 07777;
        else {
            const mode_t mask = ::umask(0);
            ::umask(mask);
            mode = 0666 & ~mask;
        }
        if (::fchmod(fd, mode) != 0) fail(std::strerror(errno));
        size_t done = 0;
        while (done < content.size()) {
            const ssize_t w = ::write(fd, content.data() + done, content.size() - done);
            if (w < 0 && errno == EINTR) continue;
            if (w <= 0) fail(std::strerror(errno));
            done += size_t(w);
        }
        if (::fsync(fd) != 0) fail(std::strerror(errno));
        if (::close(fd) != 0) {
            const std::string why = std::strerror(errno);
            std::remove(tmp.c_str());
            TempFiles::Remove(tmp);
            throw SnakeError("Cannot write \"" + path + "\": " + why + ".");
        }
        if (std::rename(tmp.c_str(), target.c_str()) != 0) {
            const std::string why = std::strerror(errno);
            std::remove(tmp.c_str());
            TempFiles::Remove(tmp);
            throw SnakeError("Cannot write \"" + path + "\": " + why + ". The existing file, if any, is unchanged.");
        }
        TempFiles::Remove(tmp);
    }
};

} // namespace tri
} // namespace vcg

#endif
