// The side of a closed snake that is inside (issue 33: Balloon that visibly works): short ticks
// from the curve into the loop, in the snake's colour. A negative Balloon deflates the loop
// towards the ticks, a positive one inflates it away from them; the inside is the side the loop
// runs round counter-clockwise seen from the front of the faces (GeometricSnake::InsideDirections),
// which is what the Balloon's sign refers to.

#include <GL/glew.h>

#include "edit_geometric_snake.h"

void EditGeometricSnakePlugin::drawInsideMarks(const Controller::Snake &s, double lift, float dpr,
                                               const unsigned char *colour)
{
    const std::vector<vcg::Point3d> in = s.InsideDirections();
    if (in.empty()) return;
    const CMeshO &cm = s.SurfacePtr()->Mesh();
    const auto &smp = s.Samples();
    const int n = int(smp.size()), every = std::max(1, (n + 23) / 24); // at most 24 ticks round the loop
    const double len = 1.2 * s.LengthScale();
    std::vector<std::pair<vcg::Point3d, vcg::Point3d>> ticks;
    for (int i = 0; i < n; i += every) {
        if (in[i].Norm() == 0) continue;
        vcg::Point3d nrm = vcg::Point3d::Construct(cm.face[smp[i].p.face].cN());
        const double l = nrm.Norm();
        const vcg::Point3d up = l > 0 && std::isfinite(l) ? nrm * (lift / l) : vcg::Point3d(0, 0, 0);
        const vcg::Point3d a = smp[i].p.Pd(cm) + up;
        ticks.push_back({a, a + in[i] * len});
    }
    for (int pass = 0; pass < 2; ++pass) { // a dark outline, then the colour
        static const unsigned char outline[3] = {20, 20, 20};
        glLineWidth((pass == 0 ? 4.f : 2.f) * dpr);
        glColor3ubv(pass == 0 ? outline : colour);
        glBegin(GL_LINES);
        for (const auto &t : ticks) {
            glVertex3d(t.first[0], t.first[1], t.first[2]);
            glVertex3d(t.second[0], t.second[1], t.second[2]);
        }
        glEnd();
    }
}
