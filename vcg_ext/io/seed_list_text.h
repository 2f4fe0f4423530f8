#ifndef VCG_EXT_SEED_LIST_TEXT_H
#define VCG_EXT_SEED_LIST_TEXT_H

// A seed list written as text, the "Seeds" parameter of the filters and the program
// ("12, 40, 77": vertex indices), read into vertex indices with a message for the user on
// anything else. Reading what a user typed is not the seed path's business
// (paths/seed_path.h joins the seeds once they are indices), and needs no mesh.

#include <cctype>
#include <climits>
#include <string>
#include <vector>

#include <vcg_ext/snake/error.h>

namespace vcg {
namespace tri {

class SeedListText
{
public:
    /// "12, 40,77" -> {12,40,77}. Separators: whitespace and/or one ',' or ';'. Empty text gives
    /// no seeds. Throws SnakeError on anything else (negative numbers, letters, ",,").
    static std::vector<int> Parse(const std::string &text)
    {
        std::vector<int> out;
        size_t i = 0;
        const size_t n = text.size();
        auto skipWs = [&]() {
            while (i < n && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
        };
        auto junk = [&](const std::string &why) {
            return SnakeError("Cannot read the seed list \"" + text + "\": " + why +
                              ". Write vertex indices separated by commas, e.g. \"12, 40, 77\".");
        };
        skipWs();
        while (i < n) {
            if (text[i] == '-') throw junk("vertex indices cannot be negative");
            if (text[i] == '+') ++i;
            if (i >= n || !std::isdigit(static_cast<unsigned char>(text[i])))
                throw junk("unexpected character '" + Utf8Char(text, i) + "' at position " + CharPosition(text, i));
            long long v = 0;
            while (i < n && std::isdigit(static_cast<unsigned char>(text[i]))) {
                v = v * 10 + (text[i] - '0');
                if (v > INT_MAX) throw junk("a vertex index is too large");
                ++i;
            }
            out.push_back(int(v));
            skipWs();
            if (i < n && (text[i] == ',' || text[i] == ';')) {
                ++i;
                skipWs();
                if (i < n && (text[i] == ',' || text[i] == ';')) throw junk("empty entry between separators");
            } else if (i < n && !std::isdigit(static_cast<unsigned char>(text[i])) && text[i] != '+' && text[i] != '-') {
                throw junk("unexpected character '" + Utf8Char(text, i) + "' at position " + CharPosition(text, i));
            }
        }
        return out;
    }

private:
    /// The whole UTF-8 character at byte i of s (" " past the end), for messages.
    static std::string Utf8Char(const std::string &s, size_t i)
    {
        if (i >= s.size()) return " ";
        size_t j = i + 1;
        while (j < s.size() && j < i + 4 && (static_cast<unsigned char>(s[j]) & 0xC0) == 0x80) ++j;
        return s.substr(i, j - i);
    }
    /// The 1-based character (not byte) position of byte i of the UTF-8 text s.
    static std::string CharPosition(const std::string &s, size_t i)
    {
        size_t k = 1;
        for (size_t b = 0; b < i && b < s.size(); ++b) k += (static_cast<unsigned char>(s[b]) & 0xC0) != 0x80;
        return std::to_string(k);
    }
};

} // namespace tri
} // namespace vcg

#endif
