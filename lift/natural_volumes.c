/*
 * natural_volumes.c — the volumes vol(S_i) of Sibson's coordinates (natural.c): how much
 * of each natural neighbour's Voronoi region the query point's region takes.
 *
 * Volumes, floating point (design):
 *   Watson's formula (Watson 1992, "Contouring", §3.7) sums signed simplices built
 *   from the circumcentres of q with every facet of every conflict simplex; near the
 *   hyperplane of an internal facet those centres run off to infinity and the sum
 *   cancels. We never form a centre for an internal facet. Instead each S_i is
 *   measured by the pyramid decomposition of a polytope's volume (Lasserre 1983,
 *   "An analytical expression and an algorithm for the volume of a convex polyhedron
 *   in R^n", JOTA 39), apex p_i:
 *       vol(S_i) = (1/d) sum_faces area(face) * (signed distance of p_i to its plane).
 *   The faces of S_i lie on bisectors, so every distance is exact from the sites:
 *     (a) on the bisector of p_i and q: q's new face with p_i; p_i is on the far
 *         side, distance -|q - p_i| / 2;
 *     (b) on the bisector of p_i and p_j, for every edge p_i p_j of a conflict
 *         simplex (no other old Voronoi face reaches into V(q)): the part of the old
 *         face dual to that edge inside V(q), distance +|p_j - p_i| / 2. That face,
 *         shared by S_i and S_j, is measured once.
 *   Face vertices, in order (Voronoi vertices are circumcentres of the dual
 *   simplices): around the edge p_i p_j the conflict simplices form one arc (V(q)
 *   cuts the convex old face by a half-plane) or the whole cycle; each gives its
 *   circumcentre, and where the arc meets the cavity's boundary through a facet F
 *   the vertex is the circumcentre of q + F (a simplex of the new triangulation,
 *   never flat: q is strictly inside the hull and not on F's plane). Face (a)'s
 *   vertices are the centres of q + F for the cavity's boundary facets F around p_i;
 *   the arc around a boundary edge p_i p_x joins the two such facets through it,
 *   which are consecutive around p_i, so each arc also gives one edge of face (a) of
 *   p_i and of p_x. Areas: a convex polygon fanned from one of its vertices into
 *   triangles of one orientation, each measured by its two shortest sides' cross
 *   product along the face's unit normal, known from the sites (tri_area2; 2D:
 *   faces are segments, lengths). Coordinates are taken relative to q and scaled
 *   by a power of two. Accuracy (tests/test_natural.c checks it): linear precision ~1e-14
 *   relative, also within 1e-15 of the hull; 2e-13 from a brute-force clipping of
 *   the cells in 2D; worse only where the hull has nearly collinear sites (hull
 *   triangles of circumradius ~1/collinearity: ~1e-4 for 1e-12).
 *   The error in vol(S_i) is a few ulps of the cones from p_i, i.e. of vol(V(q)):
 *   weights are accurate in absolute terms (not relative ones for tiny weights); a
 *   site whose computed volume is not positive (a face of zero area, exactly or
 *   within rounding) is left out. If a construction fails in floating point (q
 *   within rounding of the hull), the coordinates of q in the located simplex
 *   (linear precision too) are returned instead.
 */
#include "natural.h"
#include "geom.h"

#include <math.h>
#include <string.h>

/* Circumcentres (local coordinates) of the conflict simplices and of q (the
 * origin) with each facet on the cavity's boundary (lh__circumcenter: a pivoted
 * solve relative to the first point). Returns 0 when one is singular in floating
 * point. A far centre (a nearly flat simplex: q near the hull) is off by a few eps
 * of its distance, mostly along its axis, which moves the tip of a long spike of
 * V(q) and scales the stolen volumes alike, so the coordinates (their ratios) keep
 * their accuracy and a more precise solve would not improve them; a sliver's
 * centre is ill-determined along its axis, the line through its neighbours'
 * centres, so the face areas hardly move. */
static int centres(nn_ws *w, int d)
{
    const int nv = d + 1;
    static const double origin[NN_MAXD] = {0, 0, 0};
    for (size_t c = 0; c < w->nconf; c++) {
        const double *p[NN_MAXV];
        for (int j = 0; j < nv; j++) p[j] = w->x + (size_t)w->lv[c * nv + j] * d;
        if (!lh__circumcenter(d, d, p, w->cc + c * d)) return 0;
        for (int k = 0; k < nv; k++) {
            if (w->nb[c * nv + k] >= 0) continue;
            const double *f[NN_MAXV];
            f[0] = origin;
            for (int j = 0, i = 1; j < nv; j++)
                if (j != k) f[i++] = p[j];
            if (!lh__circumcenter(d, d, f, w->fc + (c * nv + k) * d)) return 0;
        }
    }
    return 1;
}

/* ---- volumes ----------------------------------------------------------------------- */

static double dist(const double *a, const double *b, int d)
{
    double s = 0;
    for (int k = 0; k < d; k++) s += (a[k] - b[k]) * (a[k] - b[k]);
    return sqrt(s);
}

/* Twice the area of the triangle r a b of R^3, projected on the plane with unit
 * normal n (the face's bisector plane, known exactly from the sites: the vertices'
 * own rounding off that plane is dropped, and no square root per triangle): n times
 * the cross product of the triangle's two shortest sides, whose angle is its
 * largest (Kahan's advice). Faces of V(q) near the hull are long and thin (a vertex
 * at distance ~ 1/(distance of q to the hull)); the cross product of two long,
 * nearly parallel sides, each rounded on its own, would lose the digits the
 * thinness takes (an error growing as eps / distance; the two shortest sides keep it
 * near eps). */
static double tri_area2(const double *n, const double *r, const double *a, const double *b)
{
    double e[3][3], l[3];
    for (int k = 0; k < 3; k++) {
        e[0][k] = b[k] - a[k]; /* opposite r */
        e[1][k] = r[k] - b[k]; /* opposite a */
        e[2][k] = a[k] - r[k]; /* opposite b */
    }
    for (int i = 0; i < 3; i++) l[i] = e[i][0] * e[i][0] + e[i][1] * e[i][1] + e[i][2] * e[i][2];
    int longest = l[0] >= l[1] ? (l[0] >= l[2] ? 0 : 2) : (l[1] >= l[2] ? 1 : 2);
    const double *u = e[(longest + 1) % 3], *v = e[(longest + 2) % 3];
    return fabs(n[0] * (u[1] * v[2] - u[2] * v[1]) + n[1] * (u[2] * v[0] - u[0] * v[2]) +
                n[2] * (u[0] * v[1] - u[1] * v[0]));
}

/* The unit vector along b - a, and |b - a|. */
static double unit(const double *a, const double *b, int d, double *n)
{
    double l = 0;
    for (int k = 0; k < d; k++) {
        n[k] = b[k] - a[k];
        l += n[k] * n[k];
    }
    l = sqrt(l);
    for (int k = 0; k < d; k++) n[k] /= l;
    return l;
}

/* The face of S_i and S_j on their bisector, of the given measure: adds its
 * cone from each of them, measure * |p_j - p_i| / 2. */
static void add_shared_face(nn_ws *w, int d, lh_index i, lh_index j, double measure)
{
    double h = 0.5 * dist(w->x + (size_t)i * d, w->x + (size_t)j * d, d) * measure;
    w->vol[i] += h;
    w->vol[j] += h;
}

/* An edge a b of q's new face with local site i: adds its fan triangle from the
 * face's first vertex (2D: the face is the segment; its second end gives the
 * length). */
static void add_q_face_edge(nn_ws *w, int d, lh_index i, const double *a, const double *b)
{
    double *r = w->root + (size_t)i * d;
    if (!w->rooted[i]) {
        memcpy(r, a, (size_t)d * sizeof *r);
        w->rooted[i] = 1;
    }
    if (d == 2) {
        w->aq[i] += dist(r, b, 2);
    } else {
        static const double origin[NN_MAXD] = {0, 0, 0};
        double n[NN_MAXD];
        unit(origin, w->x + (size_t)i * 3, 3, n); /* q's face with p_i: normal p_i - q */
        w->aq[i] += 0.5 * tri_area2(n, r, a, b);
    }
}

/* 2D: each edge of a conflict triangle, once: its Voronoi edge inside V(q) runs
 * from the triangle's centre to the neighbour's (both in conflict) or to the centre
 * of q + the edge (the edge is on the cavity's boundary, which then also gives one
 * end of the q-faces of its two sites; each has exactly two boundary edges). */
static void volumes_2d(nn_ws *w)
{
    for (size_t c = 0; c < w->nconf; c++)
        for (int k = 0; k < 3; k++) {
            lh_index n = w->nb[c * 3 + k], i = w->lv[c * 3 + (k + 1) % 3], j = w->lv[c * 3 + (k + 2) % 3];
            const double *cc = w->cc + c * 2;
            if (n >= 0) {
                if ((size_t)n > c) add_shared_face(w, 2, i, j, dist(cc, w->cc + (size_t)n * 2, 2));
                continue;
            }
            const double *f = w->fc + (c * 3 + k) * 2;
            add_shared_face(w, 2, i, j, dist(cc, f, 2));
            add_q_face_edge(w, 2, i, f, f);
            add_q_face_edge(w, 2, j, f, f);
        }
}

/* 3D: position of local site v in conflict tetrahedron c. */
static int pos_in(const nn_ws *w, size_t c, lh_index v)
{
    int p = 0;
    while (w->lv[c * 4 + p] != v) p++;
    return p;
}

/* The vertex of tetrahedron c that is none of i, j, x. */
static lh_index other(const nn_ws *w, size_t c, lh_index i, lh_index j, lh_index x)
{
    for (int p = 0;; p++) {
        lh_index v = w->lv[c * 4 + p];
        if (v != i && v != j && v != x) return v;
    }
}

static void mark_edge(nn_ws *w, size_t c, lh_index i, lh_index j)
{
    static const uint8_t bit[4][4] = {{0, 1, 2, 4}, {1, 0, 8, 16}, {2, 8, 0, 32}, {4, 16, 32, 0}};
    w->done[c] |= bit[pos_in(w, c, i)][pos_in(w, c, j)];
}

/* A polygon's area, fanned from its first vertex; vertices arrive in order. */
typedef struct nn_fan {
    const double *n; /* the polygon's plane's unit normal */
    const double *first, *prev;
    double area2;
} nn_fan;

static void fan_add(nn_fan *f, const double *v)
{
    if (!f->first) f->first = v;
    else if (f->prev != f->first) f->area2 += tri_area2(f->n, f->first, f->prev, v);
    f->prev = v;
}

/* 3D: the old Voronoi face of edge i j (sites of conflict tetrahedron c, k and l
 * its other two) inside V(q). The walk state (tetrahedron, x): leave across the
 * facet opposite x; in the next tetrahedron leave opposite the vertex of this one
 * that is none of i, j, x. Backwards (leaving opposite l) to the arc's first
 * tetrahedron, or round to c; then forwards, measuring. */
static void edge_face_3d(nn_ws *w, size_t c, lh_index i, lh_index j, lh_index k, lh_index l)
{
    size_t start = c, steps = 0;
    lh_index x = l;
    const double *enter = NULL;
    for (size_t s = c;; steps++) {
        int p = pos_in(w, s, x);
        lh_index n = w->nb[s * 4 + p], y = other(w, s, i, j, x);
        if (n < 0) { /* s is the arc's first tetrahedron; q + facet p its entry */
            enter = w->fc + (s * 4 + p) * 3;
            start = s;
            x = y;
            break;
        }
        if ((size_t)n == c || steps > w->nconf) { /* the whole cycle conflicts */
            x = k;
            break;
        }
        s = (size_t)n;
        x = y;
    }
    double normal[3];
    double len = unit(w->x + (size_t)i * 3, w->x + (size_t)j * 3, 3, normal);
    nn_fan fan = {normal, NULL, NULL, 0};
    if (enter) fan_add(&fan, enter);
    size_t s = start;
    for (steps = 0; steps <= w->nconf; steps++) {
        fan_add(&fan, w->cc + s * 3);
        mark_edge(w, s, i, j);
        int p = pos_in(w, s, x);
        lh_index n = w->nb[s * 4 + p], y = other(w, s, i, j, x);
        if (n < 0) { /* the arc's exit: with its entry, an edge of q's faces */
            const double *exit = w->fc + (s * 4 + p) * 3;
            fan_add(&fan, exit);
            if (enter) {
                add_q_face_edge(w, 3, i, enter, exit);
                add_q_face_edge(w, 3, j, enter, exit);
            }
            break;
        }
        if ((size_t)n == start) break;
        s = (size_t)n;
        x = y;
    }
    double cone = 0.5 * fan.area2 * 0.5 * len; /* area times |p_j - p_i| / 2 */
    w->vol[i] += cone;
    w->vol[j] += cone;
}

static void volumes_3d(nn_ws *w)
{
    static const int e[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
    for (size_t c = 0; c < w->nconf; c++)
        for (int m = 0; m < 6; m++) {
            const lh_index *v = w->lv + c * 4;
            int a = e[m][0], b = e[m][1], k = e[5 - m][0], l = e[5 - m][1];
            if (w->done[c] & (1u << m)) continue;
            edge_face_3d(w, c, v[a], v[b], v[k], v[l]);
        }
}

/* d * vol(S_i) for every local site: the shared faces were added; the face with q,
 * at distance |p_i - q| / 2 on the far side, is subtracted. */
static void finish_volumes(nn_ws *w, int d)
{
    static const double origin[NN_MAXD] = {0, 0, 0};
    for (size_t i = 0; i < w->nsite; i++)
        w->vol[i] -= 0.5 * dist(w->x + i * d, origin, d) * w->aq[i];
}

int lh__nn_volumes(nn_ws *w, int d)
{
    if (!centres(w, d)) return 0;
    if (d == 2) volumes_2d(w);
    else volumes_3d(w);
    finish_volumes(w, d);
    return 1;
}
