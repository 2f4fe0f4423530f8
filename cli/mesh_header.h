#ifndef GS_CLI_MESH_HEADER_H
#define GS_CLI_MESH_HEADER_H

// The element counts a PLY or OFF header announces, checked before vcglib's importer allocates
// them: a negative count ("element vertex -5") reached std::vector as a huge size ("Internal
// error: vector::_M_default_append", "Out of memory"), and one past int64 was read as 0 ("the
// mesh has no faces"). A count must be a whole number the file's size can hold.

#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <vcg_ext/snake/error.h>

namespace gs_cli {

class MeshHeader
{
public:
    /// Throws SnakeError naming the bad count of the PLY or OFF file `path` (`size` bytes);
    /// other formats pass.
    static void CheckCounts(const std::string &path, const std::string &ext, long long size)
    {
        std::ifstream in(path, std::ios::binary);
        if (!in) return; // the importer says why
        auto bad = [&](const std::string &why) {
            return vcg::tri::SnakeError("Cannot read the mesh \"" + path + "\": " + why + ".");
        };
        auto count = [&](const std::string &tok, const std::string &what) {
            char *e = nullptr;
            errno = 0;
            const long long n = std::strtoll(tok.c_str(), &e, 10);
            if (tok.empty() || *e || errno == ERANGE || n < 0 || n > 2147483647LL)
                throw bad("its header gives \"" + Cut(tok) + "\" as the number of " + what +
                          ", which is not a count (a whole number from 0 to 2147483647)");
            if (n > size) // every element takes at least a byte
                throw bad("its header announces " + tok + " " + what + ", more than its " + std::to_string(size) +
                          " bytes can hold (the file is damaged or cut short)");
            return n;
        };
        std::string line;
        if (ext == "ply") {
            for (int k = 0; k < 10000 && std::getline(in, line); ++k) {
                std::istringstream ls(line);
                std::string w, name, n;
                ls >> w;
                if (w == "end_header") return;
                if (w == "element" && ls >> name >> n) count(n, name == "vertex" ? "vertices" : name == "face" ? "faces" : name + " elements");
            }
        } else if (ext == "off") {
            std::string w;
            // "[ST][C][N][4][n]OFF", then the counts "nv nf ne" (comments start with #)
            std::string toks[4];
            int got = 0;
            while (got < 4 && std::getline(in, line)) {
                const size_t h = line.find('#');
                std::istringstream ls(h == std::string::npos ? line : line.substr(0, h));
                while (got < 4 && ls >> w) toks[got++] = w;
            }
            if (got < 3) return;
            size_t first = toks[0].size() >= 3 && toks[0].compare(toks[0].size() - 3, 3, "OFF") == 0 ? 1 : 0;
            if (first + 1 >= size_t(got)) return;
            count(toks[first], "vertices");
            count(toks[first + 1], "faces");
        }
    }

    /// vcglib's PLY message for a file that ends early, said plainly.
    static std::string PlyError(const std::string &msg)
    {
        if (msg.find("Unespected eof") != std::string::npos)
            return "the file ends before all the vertices and faces its header announces (it is cut short or damaged)";
        return msg;
    }

private:
    static std::string Cut(const std::string &s) { return s.size() > 40 ? s.substr(0, 37) + "..." : s; }
};

} // namespace gs_cli

#endif
