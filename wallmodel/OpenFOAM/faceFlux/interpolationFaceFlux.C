/*---------------------------------------------------------------------------*\
  SnowWall: wallmodel/OpenFOAM/faceFlux/interpolationFaceFlux.C
\*---------------------------------------------------------------------------*/
#include "interpolationFaceFlux.H"
#include "swf.h"

namespace Foam
{
    defineTypeNameAndDebug(faceFluxAddressing, 0);
    defineTypeNameAndDebug(interpolationFaceFlux, 0);
    interpolation<vector>::adddictionaryConstructorToTable
        <interpolationFaceFlux>
        addinterpolationFaceFluxvectorConstructorToTable_;
}

namespace
{
    // the summary is printed once per run, not at every construction (the
    // cloud builds its interpolations anew at every step)
    bool reported = false;

    // a cell without a flux-consistent field is named once per run
    bool fallbackNoted = false;

    // the base point of face f's fan, as the tracking takes it
    Foam::label fanBase(const Foam::polyMesh& mesh, const Foam::label f)
    {
        const Foam::label b = mesh.tetBasePtIs()[f];
        return b < 0 ? 0 : b;
    }

    // the faces of cell c in three opposite pairs; false: not a parallelepiped
    // (six quadrilaterals, each with exactly one face that shares no point,
    // each a parallelogram)
    bool hexPairs
    (
        const Foam::polyMesh& mesh,
        const Foam::label c,
        Foam::FixedList<Foam::label, 6>& pairs
    )
    {
        using namespace Foam;
        const cell& cf = mesh.cells()[c];
        if (cf.size() != 6) return false;
        const faceList& faces = mesh.faces();
        for (const label f : cf)
        {
            if (faces[f].size() != 4) return false;
        }
        FixedList<label, 6> opposite(-1);
        for (label i = 0; i < 6; ++i)
        {
            for (label j = 0; j < 6; ++j)
            {
                if (i == j) continue;
                bool shared = false;
                for (const label p : faces[cf[i]])
                {
                    if (faces[cf[j]].found(p))
                    {
                        shared = true;
                        break;
                    }
                }
                if (!shared)
                {
                    if (opposite[i] != -1) return false;
                    opposite[i] = j;
                }
            }
            if (opposite[i] == -1) return false;
        }
        label k = 0;
        FixedList<bool, 6> used(false);
        for (label i = 0; i < 6; ++i)
        {
            if (used[i]) continue;
            const label j = opposite[i];
            if (opposite[j] != i || used[j] || k == 3) return false;
            used[i] = used[j] = true;
            pairs[2*k] = cf[i];
            pairs[2*k + 1] = cf[j];
            ++k;
        }
        if (k != 3) return false;
        // a parallelepiped only: every face a parallelogram (p0 + p2 = p1 + p3
        // within 1e-3 of the face's size: points written in ascii carry six
        // digits, 1e-4 of a centimetre cell a metre from the origin). There
        // the field's normal component is uniform on each face, phi/|S|, as
        // in the tetrahedra of the cells next to it, so the velocity normal to
        // every face is the same from both sides and zero on a wall. A
        // distorted hexahedron (snapped to a surface) would carry each face's
        // flux with a normal component that varies over the face: on a wall
        // face it points into the wall in part of it, where a reflected tracer
        // is sent back into the wall at once and the tracking never ends its
        // step (met on the Ahmed body's mesh).
        const pointField& pts = mesh.points();
        for (const label f : cf)
        {
            const face& q = faces[f];
            const vector d = pts[q[0]] + pts[q[2]] - pts[q[1]] - pts[q[3]];
            const scalar size =
                mag(pts[q[2]] - pts[q[0]]) + mag(pts[q[3]] - pts[q[1]]);
            if (mag(d) > 1e-3*size) return false;
        }
        return true;
    }
}


// * * * * * * * * * * * * * * faceFluxAddressing  * * * * * * * * * * * * * //

Foam::faceFluxAddressing::faceFluxAddressing(const polyMesh& mesh)
:
    MeshObject<polyMesh, TopologicalMeshObject, faceFluxAddressing>(mesh),
    slot_(mesh.nCells(), -1)
{
    DynamicList<FixedList<label, 6>> hexes(mesh.nCells());
    FixedList<label, 6> p;
    forAll(slot_, c)
    {
        if (hexPairs(mesh, c, p))
        {
            slot_[c] = hexes.size();
            hexes.append(p);
        }
    }
    pairs_.transfer(hexes);
}


// * * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

Foam::scalar Foam::interpolationFaceFlux::outwardFlux
(
    const label c,
    const label f
) const
{
    const polyMesh& mesh = this->pMesh_;
    if (mesh.isInternalFace(f))
    {
        return mesh.faceOwner()[f] == c ? phi_[f] : -phi_[f];
    }
    const polyBoundaryMesh& bm = mesh.boundaryMesh();
    const label patchi = bm.whichPatch(f);
    const fvsPatchScalarField& pphi = phi_.boundaryField()[patchi];
    if (pphi.empty())
    {
        return 0;   // an empty patch: no flux
    }
    return pphi[f - bm[patchi].start()];
}


bool Foam::interpolationFaceFlux::fluxVelocity
(
    const label c,
    const point& x,
    vector& u
) const
{
    const FixedList<label, 6>& pairs = addr_.pairs(addr_.slot(c));
    const vectorField& Cf = this->pMeshFaceCentres_;
    swf_hex h;
    for (label k = 0; k < 3; ++k)
    {
        const label lo = pairs[2*k], hi = pairs[2*k + 1];
        for (direction i = 0; i < 3; ++i)
        {
            h.c_lo[k][i] = Cf[lo][i];
            h.c_hi[k][i] = Cf[hi][i];
        }
        h.phi_lo[k] = outwardFlux(c, lo);
        h.phi_hi[k] = outwardFlux(c, hi);
    }
    const double xp[3] = {x.x(), x.y(), x.z()};
    double up[3];
    if (swf_hex_velocity(&h, xp, up) != SWF_OK)
    {
        return false;
    }
    u = vector(up[0], up[1], up[2]);
    return true;
}


const Foam::scalarList& Foam::interpolationFaceFlux::tetFluxesOf
(
    const label c
) const
{
    const polyMesh& mesh = this->pMesh_;
    const cell& cf = mesh.cells()[c];
    HashTable<faceFluxAddressing::tetFluxes, label, Hash<label>>& cache =
        addr_.tets();
    {
        // the kept fluxes while the cell's face fluxes are the same to the bit,
        // compared in place (this runs at every interpolation: nothing is
        // allocated here); a mesh that moved in this step has new tetrahedra
        auto iter = cache.cfind(c);
        if (iter.found() && !mesh.moving() && (*iter).phi.size() == cf.size())
        {
            const scalarList& kept = (*iter).phi;
            bool same = true;
            forAll(cf, i)
            {
                if (outwardFlux(c, cf[i]) != kept[i])
                {
                    same = false;
                    break;
                }
            }
            if (same)
            {
                return (*iter).F;
            }
        }
    }
    scalarList phiC(cf.size());
    forAll(cf, i)
    {
        phiC[i] = outwardFlux(c, cf[i]);
    }
    const faceList& faces = mesh.faces();
    const pointField& pts = mesh.points();
    const vectorField& Sf = mesh.faceAreas();
    label n = 0;
    for (const label f : cf)
    {
        n += faces[f].size() - 2;
    }
    scalarList F;
    if (n >= 4 && n <= SWF_POLY_MAX)
    {
        List<FixedList<double, 3>> p(3*n);
        List<long> id(3*n);
        List<double> flux(n);
        label t = 0;
        forAll(cf, fi)
        {
            const label f = cf[fi];
            const face& fc = faces[f];
            const label m = fc.size(), base = fanBase(mesh, f);
            const bool own = mesh.faceOwner()[f] == c;
            const vector Sout = own ? Sf[f] : -Sf[f];
            const scalar S2 = magSqr(Sout);
            const scalar phiOut = phiC[fi];
            for (label i = 1; i + 1 < m; ++i)
            {
                label a = (base + i) % m, b = fc.fcIndex(a);
                if (!own) Swap(a, b);
                const label tri[3] = {fc[base], fc[a], fc[b]};
                for (label j = 0; j < 3; ++j)
                {
                    for (direction k = 0; k < 3; ++k)
                    {
                        p[3*t + j][k] = pts[tri[j]][k];
                    }
                    id[3*t + j] = tri[j];
                }
                const vector St =
                    0.5*((pts[tri[1]] - pts[tri[0]]) ^ (pts[tri[2]] - pts[tri[0]]));
                flux[t] = S2 > VSMALL ? phiOut*(St & Sout)/S2 : 0;
                ++t;
            }
        }
        swf_poly poly;
        poly.n = n;
        const point& cc = mesh.cellCentres()[c];
        for (direction k = 0; k < 3; ++k)
        {
            poly.centre[k] = cc[k];
        }
        poly.p = reinterpret_cast<const double (*)[3]>(p.cdata());
        poly.id = id.cdata();
        poly.flux = flux.cdata();
        List<double> out(4*n);
        if (swf_poly_fluxes(&poly, out.data()) == SWF_OK)
        {
            F.setSize(4*n);
            forAll(F, i)
            {
                F[i] = out[i];
            }
        }
    }
    if (F.empty() && !fallbackNoted)
    {
        fallbackNoted = true;
        Info<< "faceFlux: cell " << c << " (" << cf.size() << " faces) has no"
            << " flux-consistent field in its tetrahedra (open or degenerate);"
            << " it keeps cellPoint (noted once per run)" << endl;
    }
    faceFluxAddressing::tetFluxes entry;
    entry.phi.transfer(phiC);
    entry.F.transfer(F);
    cache.set(c, entry);
    return (*cache.cfind(c)).F;
}


bool Foam::interpolationFaceFlux::tetVelocity
(
    const tetIndices& tetIs,
    const point& x,
    vector& u
) const
{
    const label c = tetIs.cell();
    const scalarList& F = tetFluxesOf(c);
    if (F.empty())
    {
        return false;
    }
    const polyMesh& mesh = this->pMesh_;
    const cell& cf = mesh.cells()[c];
    label t = 0;
    for (const label f : cf)
    {
        if (f == tetIs.face())
        {
            break;
        }
        t += mesh.faces()[f].size() - 2;
    }
    t += tetIs.tetPt() - 1;
    if (4*t + 3 >= F.size())
    {
        return false;
    }
    const triFace tri = tetIs.faceTriIs(mesh, false);
    const pointField& pts = mesh.points();
    const point& cc = mesh.cellCentres()[c];
    double v[4][3], q[4], xp[3] = {x.x(), x.y(), x.z()}, up[3];
    for (direction k = 0; k < 3; ++k)
    {
        v[0][k] = cc[k];
        for (label j = 0; j < 3; ++j)
        {
            v[1 + j][k] = pts[tri[j]][k];
        }
    }
    for (label i = 0; i < 4; ++i)
    {
        q[i] = F[4*t + i];
    }
    if (swf_tet_velocity(v, q, xp, up) != SWF_OK)
    {
        return false;
    }
    u = vector(up[0], up[1], up[2]);
    return true;
}


void Foam::interpolationFaceFlux::report() const
{
    if (reported) return;
    reported = true;
    const polyMesh& mesh = this->pMesh_;
    scalar worst = 0;
    label worstCell = -1;
    for (label c = 0; c < mesh.nCells(); ++c)
    {
        scalar sum = 0, total = 0;
        for (const label f : mesh.cells()[c])
        {
            const scalar q = outwardFlux(c, f);
            sum += q;
            total += mag(q);
        }
        const scalar imb = total > VSMALL ? mag(sum)/total : 0;
        if (imb > worst)
        {
            worst = imb;
            worstCell = c;
        }
    }
    const label nHex = returnReduce(addr_.nHex(), sumOp<label>());
    const label nAll = returnReduce(mesh.nCells(), sumOp<label>());
    Info<< "faceFlux: " << nHex << " of " << nAll << " cells are parallelepipeds"
        << " and take the velocity from the face fluxes " << phi_.name()
        << ", " << nAll - nHex << " other cells from the fluxes in their"
        << " tetrahedra" << endl;
    const scalar worstAll = returnReduce(worst, maxOp<scalar>());
    if (worstAll > 1e-3)
    {
        if (Pstream::master())
        {
            WarningInFunction
                << "at the first tracking step (time "
                << mesh.time().timeName() << ") the fluxes " << phi_.name()
                << " break continuity: |sum phi| / sum |phi| of a cell"
                << " up to " << worstAll << "; the rebuilt velocity converges"
                << " where the fluxes do (an initial field's flux, or one"
                << " rebuilt from U, is not the solver's own)" << endl;
        }
        if (debug)
        {
            Pout<< "faceFlux: the largest imbalance here " << worst
                << " in cell " << worstCell << endl;
        }
    }
}


// * * * * * * * * * * * * * * * * Constructor * * * * * * * * * * * * * * * //

Foam::interpolationFaceFlux::interpolationFaceFlux
(
    const volVectorField& psi
)
:
    interpolationCellPoint<vector>(psi),
    phi_
    (
        [&]() -> const surfaceScalarField&
        {
            const fvMesh& mesh = psi.mesh();
            if (!mesh.foundObject<surfaceScalarField>("phi"))
            {
                FatalErrorInFunction
                    << "interpolation faceFlux of " << psi.name()
                    << ": no face flux 'phi' in the registry; it rebuilds"
                    << " the velocity from the flow's own volume fluxes"
                    << exit(FatalError);
            }
            const surfaceScalarField& phi =
                mesh.lookupObject<surfaceScalarField>("phi");
            if (phi.dimensions() != dimVolume/dimTime)
            {
                FatalErrorInFunction
                    << "interpolation faceFlux of " << psi.name()
                    << ": the flux 'phi' has dimensions " << phi.dimensions()
                    << ", not a volume flux " << dimVolume/dimTime
                    << " (a compressible solver's mass flux is not supported)"
                    << exit(FatalError);
            }
            return phi;
        }()
    ),
    addr_(faceFluxAddressing::New(psi.mesh()))
{
    report();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::interpolationFaceFlux::interpolate
(
    const vector& position,
    const label celli,
    const label facei
) const
{
    vector u;
    if (addr_.slot(celli) >= 0 && fluxVelocity(celli, position, u))
    {
        return u;
    }
    return interpolationCellPoint<vector>::interpolate(position, celli, facei);
}


Foam::vector Foam::interpolationFaceFlux::interpolate
(
    const barycentric& coordinates,
    const tetIndices& tetIs,
    const label facei
) const
{
    vector u;
    const point x = tetIs.tet(this->pMesh_).barycentricToPoint(coordinates);
    if
    (
        addr_.slot(tetIs.cell()) >= 0
      ? fluxVelocity(tetIs.cell(), x, u)
      : tetVelocity(tetIs, x, u)
    )
    {
        return u;
    }
    return interpolationCellPoint<vector>::interpolate
    (
        coordinates,
        tetIs,
        facei
    );
}
