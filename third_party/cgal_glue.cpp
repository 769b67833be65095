// The one translation unit that includes CGAL (third_party/cgal_glue.h says why).
#include "third_party/cgal_glue.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>


namespace cgal_glue {

namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using CP = K::Point_2;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, CGAL::Default, CGAL::Exact_predicates_tag>;
using DT = CGAL::Delaunay_triangulation_2<K>;

CP to_cgal(Point p) { return CP(double(p.x), double(p.y)); }
Point from_cgal(const CP& p) { return Point{std::int32_t(p.x()), std::int32_t(p.y())}; }
}  // namespace

struct ConstrainedDelaunay::Impl {
    CDT cdt;
};

ConstrainedDelaunay::ConstrainedDelaunay() : impl_(new Impl) {}
ConstrainedDelaunay::~ConstrainedDelaunay() = default;

void ConstrainedDelaunay::insert(Point p) { impl_->cdt.insert(to_cgal(p)); }

void ConstrainedDelaunay::insert_constraint(Point a, Point b) {
    if (a != b) impl_->cdt.insert_constraint(to_cgal(a), to_cgal(b));
}

bool ConstrainedDelaunay::remove(Point p) {
    CDT& cdt = impl_->cdt;
    CDT::Locate_type lt;
    int li = 0;
    const CDT::Face_handle f = cdt.locate(to_cgal(p), lt, li);
    if (lt != CDT::VERTEX) return false;
    const CDT::Vertex_handle v = f->vertex(li);
    if (cdt.are_there_incident_constraints(v)) return false;
    cdt.remove(v);
    return true;
}

Mesh ConstrainedDelaunay::mesh() const {
    const CDT& cdt = impl_->cdt;
    Mesh m;
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) m.vertices.push_back(from_cgal(v->point()));
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
        m.faces.push_back({from_cgal(f->vertex(0)->point()), from_cgal(f->vertex(1)->point()), from_cgal(f->vertex(2)->point())});
        for (int i = 0; i < 3; ++i) {
            if (!f->is_constrained(i)) continue;
            // Each constrained edge once: from the face whose address is smaller, or the only finite one.
            const CDT::Face_handle g = f->neighbor(i);
            if (!cdt.is_infinite(g) && &*g < &*f) continue;
            m.constrained.push_back({from_cgal(f->vertex(CDT::ccw(i))->point()), from_cgal(f->vertex(CDT::cw(i))->point())});
        }
    }
    return m;
}

struct Delaunay::Impl {
    DT dt;
    std::vector<DT::Vertex_handle> handles;
};

Delaunay::Delaunay() : impl_(new Impl) {}
Delaunay::~Delaunay() = default;

void Delaunay::insert(const std::vector<Point>& points) {
    std::vector<CP> cps;
    cps.reserve(points.size());
    for (const Point p : points) cps.push_back(to_cgal(p));
    impl_->dt.insert(cps.begin(), cps.end());  // spatially sorted by CGAL
    // Each point's vertex, located by a walk from the previous one.
    impl_->handles.assign(points.size(), DT::Vertex_handle());
    DT::Face_handle hint;
    for (std::size_t i = 0; i < points.size(); ++i) {
        DT::Locate_type lt;
        int li = 0;
        const DT::Face_handle f = impl_->dt.locate(cps[i], lt, li, hint);
        if (lt == DT::VERTEX) impl_->handles[i] = f->vertex(li);
        hint = f;
    }
}

void Delaunay::remove(std::size_t index) { impl_->dt.remove(impl_->handles[index]); }

std::size_t Delaunay::face_count() const { return impl_->dt.number_of_faces(); }

bool Delaunay::valid() const { return impl_->dt.is_valid(); }

}  // namespace cgal_glue
