#ifndef VCG_EXT_SNAKE_PARAM_TABLE_H
#define VCG_EXT_SNAKE_PARAM_TABLE_H

// A table of parameters defined once (ParamDef: name, command-line option, dialog label,
// default, accepted range, help) and the values read against it (ParamValues), checked with
// the same messages whichever host filled them. The tables of the geometric snake operations
// are in session/param_defs.h.

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <vcg_ext/snake/error.h>

namespace vcg {
namespace tri {

/// One value of an enumerated parameter: the command-line word and the dialog label.
struct ParamChoice
{
    std::string key;
    std::string label;
};

/// One parameter. Values are held as double (bool 0/1, int, real, enum index) or as text.
struct ParamDef
{
    enum Kind { Bool, Int, Real, Enum, Text };
    Kind kind = Real;
    std::string name;   ///< MeshLab parameter name, e.g. "ExternalWeight" (scripts refer to it)
    std::string option; ///< command-line option without "--", e.g. "external-weight"; empty: none
    std::string label;  ///< dialog label
    double value = 0;   ///< default (Bool, Int, Real, Enum index)
    std::string text;   ///< default (Text)
    double min = 0, max = 0;
    bool openMin = false; ///< the range excludes min
    std::vector<ParamChoice> choices; ///< Enum only
    std::string help;   ///< may hold simple HTML (<b>, <i>, <code>) for MeshLab's dialog

    static ParamDef MakeBool(const std::string &name, const std::string &option, const std::string &label, bool dflt,
                             const std::string &help)
    {
        return Make(Bool, name, option, label, dflt ? 1 : 0, 0, 1, help);
    }
    static ParamDef MakeInt(const std::string &name, const std::string &option, const std::string &label, int dflt,
                            int lo, int hi, const std::string &help)
    {
        return Make(Int, name, option, label, dflt, lo, hi, help);
    }
    static ParamDef MakeReal(const std::string &name, const std::string &option, const std::string &label, double dflt,
                             double lo, double hi, const std::string &help, bool openMin = false)
    {
        ParamDef d = Make(Real, name, option, label, dflt, lo, hi, help);
        d.openMin = openMin;
        return d;
    }
    static ParamDef MakeEnum(const std::string &name, const std::string &option, const std::string &label, int dflt,
                             const std::vector<ParamChoice> &choices, const std::string &help)
    {
        ParamDef d = Make(Enum, name, option, label, dflt, 0, double(choices.size()) - 1, help);
        d.choices = choices;
        return d;
    }
    static ParamDef MakeText(const std::string &name, const std::string &option, const std::string &label,
                             const std::string &dflt, const std::string &help)
    {
        ParamDef d = Make(Text, name, option, label, 0, 0, 0, help);
        d.text = dflt;
        return d;
    }

    /// "[0, 10000]", "(0, 1e+06]", "normal|curvature|quadric".
    std::string RangeText() const
    {
        if (kind == Enum) {
            std::string s;
            for (const auto &c : choices) s += (s.empty() ? "" : "|") + c.key;
            return s;
        }
        std::ostringstream o;
        o.precision(12);
        o << (openMin ? "(" : "[") << min << ", " << max << "]";
        return o.str();
    }
    /// The default as the command line writes it.
    std::string DefaultText() const
    {
        switch (kind) {
        case Bool: return value != 0 ? "on" : "off";
        case Enum: return choices[size_t(value)].key;
        case Text: return text;
        default: {
            std::ostringstream o;
            o.precision(12);
            o << value;
            return o.str();
        }
        }
    }

private:
    static ParamDef Make(Kind k, const std::string &name, const std::string &option, const std::string &label,
                         double dflt, double lo, double hi, const std::string &help)
    {
        ParamDef d;
        d.kind = k;
        d.name = name;
        d.option = option;
        d.label = label;
        d.value = dflt;
        d.min = lo;
        d.max = hi;
        d.help = help;
        return d;
    }
};

/// Values of one operation's parameters, starting at the defaults. The MeshLab filter fills it
/// from its RichParameterList, the program from its options; Check() then refuses values out
/// of range with the same message in both (naming the parameter as the user wrote it).
class ParamValues
{
public:
    explicit ParamValues(const std::vector<ParamDef> &defs) : defs_(&defs)
    {
        for (const auto &d : defs) {
            num_[d.name] = d.kind == ParamDef::Real ? double(float(d.value)) : d.value; // see SetNumber
            text_[d.name] = d.text;
        }
    }
    const std::vector<ParamDef> &Defs() const { return *defs_; }
    const ParamDef &Def(const std::string &name) const
    {
        for (const auto &d : *defs_)
            if (d.name == name) return d;
        throw SnakeError("Unknown parameter \"" + name + "\".");
    }
    const ParamDef *FindOption(const std::string &option) const
    {
        for (const auto &d : *defs_)
            if (!d.option.empty() && d.option == option) return &d;
        return nullptr;
    }

    /// Real parameters have float precision, as MeshLab stores them (RichFloat): the same
    /// text gives the same value in a script and on the command line.
    void SetNumber(const std::string &name, double v)
    {
        const ParamDef &d = Def(name);
        num_[name] = (d.kind == ParamDef::Real && std::isfinite(v) && std::fabs(v) < 3e38) ? double(float(v)) : v;
        set_[name] = true;
    }
    void SetText(const std::string &name, const std::string &v)
    {
        Def(name);
        text_[name] = v;
        set_[name] = true;
    }
    /// Parses a command-line value ("0.3", "12", "on"/"off", an enum key or label, any text).
    /// `who` names the parameter in messages (e.g. "--alpha").
    void Parse(const ParamDef &d, const std::string &v, const std::string &who)
    {
        auto bad = [&](const std::string &expect) {
            return SnakeError(who + " expects " + expect + ", not \"" + v + "\".");
        };
        switch (d.kind) {
        case ParamDef::Text: SetText(d.name, v); return;
        case ParamDef::Bool: {
            std::string s = Lower(v);
            if (s == "1" || s == "on" || s == "true" || s == "yes") SetNumber(d.name, 1);
            else if (s == "0" || s == "off" || s == "false" || s == "no") SetNumber(d.name, 0);
            else throw bad("on or off");
            return;
        }
        case ParamDef::Enum: {
            const std::string s = Lower(v);
            for (size_t i = 0; i < d.choices.size(); ++i)
                if (s == Lower(d.choices[i].key) || s == Lower(d.choices[i].label)) {
                    SetNumber(d.name, double(i));
                    return;
                }
            throw bad("one of " + d.RangeText());
        }
        case ParamDef::Int: {
            const char *b = v.c_str();
            char *e = nullptr;
            const long long x = std::strtoll(b, &e, 10);
            if (v.empty() || *e != '\0') throw bad("an integer");
            SetNumber(d.name, double(x));
            return;
        }
        case ParamDef::Real: {
            const char *b = v.c_str();
            char *e = nullptr;
            const double x = std::strtod(b, &e);
            if (v.empty() || *e != '\0') throw bad("a number");
            if (x != 0 && std::fabs(x) < double(std::numeric_limits<float>::min())) // would read as 0
                throw SnakeError(who + " " + v + " is too close to 0: parameters are kept in single precision, as "
                                 "MeshLab keeps them (0, or at least 1.2e-38 in magnitude).");
            SetNumber(d.name, x);
            return;
        }
        }
    }

    /// Throws SnakeError for the first value out of its range. `cli`: name parameters by their
    /// command-line option ("--alpha") instead of their MeshLab name ("Alpha").
    void Check(bool cli = false) const
    {
        for (const auto &d : *defs_) {
            if (d.kind == ParamDef::Text || d.kind == ParamDef::Bool) continue;
            const double v = num_.at(d.name);
            const bool low = d.openMin ? !(v > d.min) : !(v >= d.min);
            if (std::isfinite(v) && !low && v <= d.max) continue;
            const std::string who = cli && !d.option.empty() ? "--" + d.option : d.name;
            std::ostringstream o;
            if (d.kind == ParamDef::Enum && cli) {
                o << who << " must be one of " << d.RangeText() << ", not " << v << ".";
            } else if (d.kind == ParamDef::Enum) {
                o << who << " must be";
                for (size_t i = 0; i < d.choices.size(); ++i)
                    o << (i == 0 ? " " : i + 1 == d.choices.size() ? " or " : ", ") << i << " ("
                      << d.choices[i].label << ")";
                o << ", not " << v << ".";
            } else {
                o << who << " must be in " << d.RangeText() << ", not ";
                if (v == std::floor(v) && std::fabs(v) < 1e15) o << (long long)v << ".";
                else {
                    o.precision(9);
                    o << v << ".";
                }
            }
            throw SnakeError(o.str());
        }
    }

    double Real(const std::string &name) const { return num_.at(Def(name).name); }
    int Int(const std::string &name) const { return int(num_.at(Def(name).name)); }
    int Enum(const std::string &name) const { return int(num_.at(Def(name).name)); }
    bool Bool(const std::string &name) const { return num_.at(Def(name).name) != 0; }
    const std::string &Text(const std::string &name) const { return text_.at(Def(name).name); }
    bool IsSet(const std::string &name) const { return set_.count(name) > 0; }

    static std::string Lower(std::string s)
    {
        for (auto &c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
        return s;
    }

private:
    const std::vector<ParamDef> *defs_;
    std::map<std::string, double> num_;
    std::map<std::string, std::string> text_;
    std::map<std::string, bool> set_;
};

} // namespace tri
} // namespace vcg

#endif
