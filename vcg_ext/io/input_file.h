#ifndef VCG_EXT_INPUT_FILE_H
#define VCG_EXT_INPUT_FILE_H

// The one check before the project reads any file the user names (a mesh, a Pick Points file,
// a curve or session JSON, a batch file): it must be a regular, readable file. A FIFO, a device
// or a socket would block the reader forever (or stream without end), so it is refused at
// once, in the filters, the edit tool and the program alike.

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include <vcg_ext/snake/error.h>

namespace vcg {
namespace tri {

class InputFile
{
public:
    /// Throws SnakeError ("Cannot read <what> "<path>": ...") unless `path` is a regular file
    /// this process may read. `what` names it for the user, e.g. "the Pick Points file".
    static void Require(const std::string &path, const std::string &what)
    {
        const std::string head = "Cannot read " + what + " \"" + path + "\": ";
        if (path.empty()) throw SnakeError("No file name given for " + what + ".");
        struct stat st;
        if (::stat(path.c_str(), &st) != 0) throw SnakeError(head + std::strerror(errno) + ".");
        if (S_ISDIR(st.st_mode)) throw SnakeError(head + "it is a folder, not a file.");
        if (!S_ISREG(st.st_mode))
            throw SnakeError(head + "it is not a regular file (a pipe, device or socket would never end or block "
                                    "the reading), so it is not read.");
        if (::access(path.c_str(), R_OK) != 0) throw SnakeError(head + std::strerror(errno) + ".");
    }
};

} // namespace tri
} // namespace vcg

#endif
