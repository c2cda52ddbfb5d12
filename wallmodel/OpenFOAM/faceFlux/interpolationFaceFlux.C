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

    // the faces of cell c in three opposite pairs; false: not a hexahedron
    // (six quadrilaterals, each with exactly one face that shares no point)
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
        return k == 3;
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


void Foam::interpolationFaceFlux::report() const
{
    if (reported) return;
    reported = true;
    const polyMesh& mesh = this->pMesh_;
    scalar worst = 0;
    label worstCell = -1;
    for (label c = 0; c < mesh.nCells(); ++c)
    {
        const label s = addr_.slot(c);
        if (s < 0) continue;
        scalar sum = 0, total = 0;
        for (const label f : addr_.pairs(s))
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
    Info<< "faceFlux: " << nHex << " of " << nAll << " cells are hexahedra"
        << " and take the velocity from the face fluxes " << phi_.name()
        << ", " << nAll - nHex << " cellPoint" << endl;
    const scalar worstAll = returnReduce(worst, maxOp<scalar>());
    if (worstAll > 1e-3)
    {
        if (Pstream::master())
        {
            WarningInFunction
                << "at the first tracking step (time "
                << mesh.time().timeName() << ") the fluxes " << phi_.name()
                << " break continuity: |sum phi| / sum |phi| of a hexahedron"
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
    if
    (
        addr_.slot(tetIs.cell()) >= 0
     && fluxVelocity
        (
            tetIs.cell(),
            tetIs.tet(this->pMesh_).barycentricToPoint(coordinates),
            u
        )
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
