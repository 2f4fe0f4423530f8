#ifndef VCG_EXT_SNAKE_PARAM_DEFS_H
#define VCG_EXT_SNAKE_PARAM_DEFS_H

// The parameters of the geometric snake operations, defined once: name (as MeshLab scripts
// write it), command-line option, dialog label, default, accepted range and help. The MeshLab
// filters build their parameter lists from these tables and the `geometric-snake` program
// builds its options from them, so both have the same defaults, ranges and error messages.
//
// Adding a parameter is one entry in the table of its operation (plus the line that uses the
// value). Defaults of engine parameters are read from SnakeParams, so they stay in one place.
// A table's rows and the values read against it: session/param_table.h.

#include <string>
#include <vector>

#include <vcg_ext/energy/crease_energy.h>
#include <vcg_ext/energy/feature_energy.h>
#include <vcg_ext/paths/seed_path.h>
#include <vcg_ext/session/param_table.h>
#include <vcg_ext/snake/error.h>
#include <vcg_ext/snake/geometric_snake.h>

namespace vcg {
namespace tri {

/// The parameter tables of the four operations (MeshLab filters / program subcommands).
class SnakeParamDefs
{
public:
    typedef ParamDef D;

    static int DefaultSmoothingSteps() { return 2; }
    static int MaxSmoothingSteps() { return 10000; }

    static const std::vector<ParamChoice> &EnergyChoices()
    {
        static const std::vector<ParamChoice> c = {
            {"normal", "Normal variation"}, {"curvature", "Curvature norm"}, {"quadric", "Quadric error"},
            {"crease", "Crease distance (CAD)"}, {"part", "Part boundary (concave)"}};
        return c;
    }

    static std::string EnergyTypeHelp()
    {
        return "How features are measured. <b>Normal variation</b> (paper, Eq. 6): how much the normals of the "
               "faces around a vertex differ. <b>Curvature norm</b>: the norm of the principal curvatures. "
               "<b>Quadric error</b>: the distance error of the vertex's face-plane quadric. These three live at "
               "vertices and are normalised to [0,1], 0 = feature. <b>Crease distance (CAD)</b>, for CAD "
               "tessellations (flat faces made of long slivers, every vertex on a crease): the sharp edges are "
               "found from dihedral angles (<i>Crease angle</i>) and the energy at any surface point grows with "
               "its distance d to the nearest crease of its face, 1 - exp(-(d/w)^2), with w = (1 + smoothing "
               "steps) / 18 of the local feature size (how far the face reaches across that crease); the vertex "
               "quality gets its values at the vertices. "
               "<b>Part boundary (concave)</b>, for closed loops around parts of organic meshes and scans (a "
               "finger, a leg, an ear's base, an eye's rim, a bottle's neck): low only on concave valleys (the "
               "minima rule: parts meet along lines of negative minimum curvature), 1 on flat, convex and "
               "ridge-like ground, with the curvature fitted over (1 + smoothing steps) local edge lengths so "
               "scan noise makes no wells. Pick it to snake around a part; keep normal variation for creases "
               "and ridges, which it ignores when they are convex.";
    }
    static ParamDef CreaseAngleDef()
    {
        return D::MakeReal("CreaseAngle", "crease-angle", "Crease angle", DefaultCreaseAngle(), 1,
            179,
            "For the crease energy: an edge whose two faces' normals differ by more than this angle (degrees) "
            "is a crease. The default keeps the edges of blocks, bores and pockets and leaves out the facets "
            "of cylinders tessellated with 16 or more segments.");
    }
    static ParamDef MergeDuplicatesDef()
    {
        return D::MakeBool("MergeDuplicateVertices", "merge-duplicates", "Merge duplicate vertices", false,
            "If the mesh is a triangle soup (its faces do not share vertices, as in STL files), merge the "
            "vertices at identical positions first (like Filters > Cleaning and Repairing > Merge Close "
            "Vertices with distance 0; vertex indices change). Off: a soup is refused with a message.");
    }
    static ParamDef SeedPointsDef()
    {
        return D::MakeText("SeedPoints", "seed-points", "Seed points", "",
            "Seeds as 3D points, used when <i>Seed vertices</i> is empty: <code>x y z; x y z; ...</code> (the "
            "mesh's own coordinates). Each is moved to the closest point of the surface; the curve starts and "
            "ends exactly there, inside a face if need be. Points farther from the surface than 10% of the "
            "bounding box diagonal are refused.");
    }
    static ParamDef SeedFileDef()
    {
        return D::MakeText("SeedFile", "pp", "Seed file (.pp)", "",
            "Seeds from a MeshLab <i>Pick Points</i> file (.pp, saved by Edit > PickPoints), in the file's "
            "order, used when <i>Seed vertices</i> and <i>Seed points</i> are empty; points left unplaced "
            "(inactive) are skipped. Snapped onto the surface like <i>Seed points</i>.");
    }

    /// Compute Geometric Snake Feature Energy / `geometric-snake energy`.
    static const std::vector<ParamDef> &FeatureEnergy()
    {
        static const std::vector<ParamDef> d = {
            D::MakeEnum("EnergyType", "type", "Energy type", 0, EnergyChoices(), EnergyTypeHelp()),
            D::MakeInt("SmoothingSteps", "smoothing", "Smoothing steps", DefaultSmoothingSteps(), 0,
                MaxSmoothingSteps(),
                "Number of Laplacian smoothing passes over the per-vertex energy before normalisation "
                "(0 = none). A little smoothing removes noise and widens the basin of attraction of "
                "features. For the crease energy it widens the basin by distance: w = (1 + steps) / 18 of the "
                "local feature size."),
            CreaseAngleDef(),
            MergeDuplicatesDef(),
            D::MakeBool("Colorize", "colorize", "Colorize by energy", true,
                "Also colour the vertices by the energy with MeshLab's quality colour ramp over [0,1] "
                "(red = feature, blue = flat). Adds per-vertex colour to the mesh."),
        };
        return d;
    }

    /// Geometric Snake Seed Path / `geometric-snake path`.
    static const std::vector<ParamDef> &SeedPath()
    {
        static const std::vector<ParamDef> d = {
            D::MakeText("Seeds", "seeds", "Seed vertices", "",
                "Comma-separated 0-based vertex indices, in file order (the order of the vertices in the "
                "loaded file), e.g. <code>0, 57, 112</code>. At least two; the path visits them in "
                "this order."),
            SeedPointsDef(),
            SeedFileDef(),
            D::MakeBool("Closed", "closed", "Closed path", false,
                "Also join the last seed back to the first one (a closed snake)."),
            D::MakeEnum("Cost", "cost", "Path cost", 0, {{"length", "Length"}, {"feature", "Feature"}},
                "<b>Length</b>: shortest path along edges. <b>Feature</b>: edge lengths weighted by the "
                "vertex quality (the feature energy, expected in [0,1]) so the path prefers features; "
                "if the mesh has no vertex quality, the normal-variation energy is computed first and "
                "stored in the vertex quality."),
            MergeDuplicatesDef(),
            D::MakeBool("NewLayer", "", "Add path as new layer", true,
                "Also add the path as a new layer named \"Seed path\" made of its vertices and edges. "
                "The current layer stays the input mesh."),
        };
        return d;
    }

    /// Geometric Snake from Seed Vertices / `geometric-snake snake`.
    static const std::vector<ParamDef> &Snake()
    {
        static const SnakeParams p;
        static const std::vector<ParamDef> d = {
            D::MakeText("Seeds", "seeds", "Seed vertices", "",
                "Comma-separated 0-based vertex indices, in file order, near the feature to capture, in "
                "the order the curve visits them (at least 2; 3 for a closed snake)."),
            SeedPointsDef(),
            SeedFileDef(),
            D::MakeBool("Closed", "closed", "Closed snake", false,
                "Join the last seed back to the first: a closed curve."),
            D::MakeBool("CompleteLoop", "complete-loop", "Complete a stroke into a loop", false,
                "The seeds are an open stroke across a part (a limb, a finger, an ear), from one side of it to "
                "the other on one side: complete it into a closed snake round the part, the stroke plus the "
                "shortest way back round the other side (contour completion, Lee et al. 2004). Leave "
                "<i>Closed snake</i> off."),
            D::MakeEnum("EnergyType", "energy", "Energy type", 0, EnergyChoices(),
                EnergyTypeHelp() + " Computed with 2 smoothing steps and stored in the vertex quality; "
                "<i>Use vertex quality</i> overrides it."),
            CreaseAngleDef(),
            D::MakeReal("Alpha", "alpha", "Alpha (tension)", p.alpha, 0, 1e4,
                "Weight of the first-derivative (tension) term of the spline energy, Eq. 2. Scale-free "
                "(positions are measured in mean edge lengths)."),
            D::MakeReal("Beta", "beta", "Beta (rigidity)", p.beta, 0, 1e4,
                "Weight of the second-derivative (rigidity) term of the spline energy, Eq. 2: larger "
                "gives smoother curves."),
            D::MakeReal("Gamma", "gamma", "Gamma (inverse step)", p.gamma, 0, 1e6,
                "Inverse time step of the update, Eq. 4: larger moves the snake in smaller, steadier "
                "steps.", true),
            D::MakeReal("ExternalWeight", "external-weight", "External weight", p.externalWeight, 0, 1e4,
                "Weight of the feature force (the gradient of the energy, which lies in [0,1]) against "
                "the spline energy."),
            D::MakeReal("Balloon", "balloon", "Balloon (pressure)", p.balloon, -10, 10,
                "Closed snakes: a pressure along the curve's normal, as in image snakes: &gt; 0 inflates the "
                "snake towards a rim around it, &lt; 0 deflates it towards a feature inside it; 0 (the "
                "paper) none. It acts where the energy is high and fades on features, so a rim holds a "
                "gently inflated snake: 0.1-0.3 is a good start. Open snakes ignore it."),
            D::MakeReal("Spacing", "spacing", "Sample spacing", p.spacing, 0.05, 1000,
                "Distance between snake samples, in mean edge lengths of the mesh."),
            D::MakeInt("MaxOperations", "max-operations", "Max operations", 500, 0, 1000000,
                "Upper limit on snake operations (one embedding + up to 5 updates each); the snake "
                "usually converges much earlier. A run that reaches it ends and says so."),
            D::MakeReal("TimeLimit", "time-limit", "Time limit (s)", 0, 0, 1e6,
                "Upper limit on the run's wall time in seconds (0: none). A run that reaches it ends and "
                "says so; the curve is kept as it is."),
            D::MakeEnum("Method", "method", "Method", int(p.method),
                {{"embedding", "Local embedding (paper)"}, {"projection", "3D update + projection"}},
                "<b>Local embedding</b>: the paper's method, updates in the plane of a local "
                "parameterization. <b>3D update + projection</b>: the naive alternative of Sec. 4.2, for "
                "comparison."),
            D::MakeBool("UseQuality", "use-quality", "Use vertex quality", false,
                "Take the feature energy from the current vertex quality (low = feature; any range, it "
                "is normalized) instead of computing the energy of <i>Energy type</i>."),
            MergeDuplicatesDef(),
            D::MakeText("OutputFile", "", "Output file", "",
                "Where to write the final curve; the extension chooses the format: .json (samples, "
                "initial and final curve, timings), .obj (l records) or .ply (edges). Empty: no file."),
            D::MakeBool("NewLayer", "", "Add curve as new layer", true,
                "Also add the final curve as a new layer made of vertices and edges."),
        };
        return d;
    }

    /// Cut Mesh along Geometric Snake / `geometric-snake cut` (vcg_ext/cut/mesh_cut.h).
    static const std::vector<ParamDef> &Cut()
    {
        static const std::vector<ParamDef> d = {
            D::MakeText("CurveFile", "curve", "Curve file", "",
                "A snake curve file (.json, as the edit tool, <i>Export Geometric Snake Curves</i> or "
                "<code>geometric-snake snake</code> write it) made on this mesh. In MeshLab, empty: the snakes "
                "kept on the mesh, else the edit tool's session file next to it."),
            D::MakeInt("SnakeIndex", "snake", "Snake", -1, -1, 100000,
                "Which snake of a session or file holding several (0-based); -1: the selected one."),
            D::MakeEnum("Mode", "mode", "Mode", 0,
                {{"select", "Select"}, {"select-only", "Select only (mesh unchanged)"}, {"split", "Split in two"},
                 {"cut-open", "Cut open"}},
                "<b>Select</b>: embed the curve and select the faces of one side. <b>Select only</b>: select "
                "the faces whose centroid is on that side; the mesh is not changed. <b>Split</b>: two parts, "
                "inside and outside. <b>Cut open</b>: the curve's edges become boundary edges."),
            D::MakeEnum("Side", "side", "Side", 0,
                {{"smaller", "Smaller part"}, {"larger", "Larger part"}, {"inside", "Inside"}, {"outside", "Outside"}},
                "The side selected or split off as \"inside\": the smaller or larger part by area, or the "
                "side the closed snake's normal points away from (where the Balloon inflates; for an open "
                "snake its left)."),
            D::MakeBool("Split", "split", "Split", false,
                "Split in two (as mode split): writes OUT_inside.ply and OUT_outside.ply."),
        };
        return d;
    }

    /// Export Geometric Snake Curves (no program subcommand: the program writes its curves itself).
    static const std::vector<ParamDef> &Export()
    {
        static const std::vector<ParamDef> d = {
            D::MakeText("OutputFile", "", "Output file", "", "File to write: .json, .obj or .ply (by extension)."),
            D::MakeEnum("Which", "", "Which snakes", 0, {{"all", "All snakes"}, {"selected", "Selected snake"}},
                "All the snakes kept on the mesh, or only the one selected in the edit tool."),
            D::MakeBool("NewLayer", "", "Add curves as new layer", false,
                "Also add the curves as a new layer made of vertices and edges."),
        };
        return d;
    }

    /// The engine parameters of a checked set of Snake() values.
    static SnakeParams ToSnakeParams(const ParamValues &v)
    {
        SnakeParams p;
        p.alpha = v.Real("Alpha");
        p.beta = v.Real("Beta");
        p.gamma = v.Real("Gamma");
        p.externalWeight = v.Real("ExternalWeight");
        p.spacing = v.Real("Spacing");
        p.balloon = v.Real("Balloon");
        p.method = SnakeMethod(v.Enum("Method"));
        p.Validate();
        return p;
    }
};

} // namespace tri
} // namespace vcg

#endif
