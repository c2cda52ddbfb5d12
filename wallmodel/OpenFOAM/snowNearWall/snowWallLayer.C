/*---------------------------------------------------------------------------*\
  SnowWall: wallmodel/OpenFOAM/snowNearWall/snowWallLayer.C (see the .H)
\*---------------------------------------------------------------------------*/
#include "snowWallLayer.H"
#include "turbulenceModel.H"
#include "indexedOctree.H"
#include "treeDataFace.H"
#include "Random.H"

Foam::labelList Foam::snowNearestWallFace
(
    const polyMesh& mesh,
    const labelList& patches
)
{
    const polyBoundaryMesh& bm = mesh.boundaryMesh();
    DynamicList<label> faces;
    for (const label pi : patches)
    {
        const polyPatch& pp = bm[pi];
        forAll(pp, i)
        {
            faces.append(pp.start() + i);
        }
    }
    labelList nearest(mesh.nCells(), label(-1));
    if (faces.empty())
    {
        return nearest;     // no wall of these patches on this processor
    }
    treeBoundBox bb(mesh.points());
    Random rndGen(123456);
    bb = bb.extend(rndGen, 1e-4);
    bb.min() -= point::uniform(ROOTVSMALL);
    bb.max() += point::uniform(ROOTVSMALL);

    const labelList faceLabels(faces);
    indexedOctree<treeDataFace> tree
    (
        treeDataFace(false, mesh, faceLabels),
        bb, 8, 10, 3.0
    );
    const pointField& cc = mesh.cellCentres();
    const scalar span2 = magSqr(bb.span());
    forAll(cc, celli)
    {
        const pointIndexHit hit = tree.findNearest(cc[celli], span2);
        if (hit.hit())
        {
            nearest[celli] = faceLabels[hit.index()];
        }
    }
    return nearest;
}


void Foam::snowFrictionVelocity
(
    const turbulenceModel& turb,
    const labelList& patches,
    scalarField& uTau
)
{
    const fvMesh& mesh = turb.mesh();
    const volVectorField& U = turb.U();
    uTau.setSize(mesh.nBoundaryFaces());
    uTau = 0;
    for (const label pi : patches)
    {
        const polyPatch& pp = mesh.boundaryMesh()[pi];
        const vectorField snGradU(U.boundaryField()[pi].snGrad());
        const scalarField nuEff(turb.nuEff(pi));
        const vectorField& n = pp.faceNormals();
        forAll(pp, i)
        {
            const vector g = snGradU[i] - (snGradU[i] & n[i])*n[i];
            uTau[pp.start() + i - mesh.nInternalFaces()] = sqrt(nuEff[i]*mag(g));
        }
    }
}


Foam::scalar Foam::snowWallDistance
(
    const polyMesh& mesh,
    const label facei,
    const point& x
)
{
    return mesh.faces()[facei].nearestPoint(x, mesh.points()).distance();
}


Foam::labelList Foam::snowWallPatches
(
    const polyBoundaryMesh& bm,
    const dictionary& dict,
    const word& who
)
{
    const wordRes sel(dict.get<wordRes>("patches"));
    if (sel.empty())
    {
        FatalIOErrorInFunction(dict)
            << who << ": 'patches' is empty: name the walls"
            << exit(FatalIOError);
    }
    for (const wordRe& w : sel)
    {
        bool any = false;
        for (const polyPatch& pp : bm)
        {
            any = any || w.match(pp.name());
        }
        if (!any)
        {
            FatalIOErrorInFunction(dict)
                << who << ": patches: '" << w << "' matches no patch"
                << " (patches: " << bm.names() << ")" << exit(FatalIOError);
        }
    }
    DynamicList<label> ids;
    for (const polyPatch& pp : bm)
    {
        if (sel.match(pp.name()))
        {
            if (pp.coupled() || polyPatch::constraintType(pp.type()))
            {
                FatalIOErrorInFunction(dict)
                    << who << ": patch " << pp.name() << " is a " << pp.type()
                    << " patch, not a wall" << exit(FatalIOError);
            }
            ids.append(pp.index());
        }
    }
    return labelList(ids);
}


const Foam::turbulenceModel* Foam::snowFindTurbulence
(
    const fvMesh& mesh,
    const word& group
)
{
    return mesh.findObject<turbulenceModel>
    (
        IOobject::groupName(turbulenceModel::propertiesName, group)
    );
}


void Foam::snowCellPointValueGrad
(
    const polyMesh& mesh,
    const scalarField& cellValues,
    const scalarField& pointValues,
    const tetIndices& tetIs,
    const barycentric& c,
    scalar& value,
    vector& grad
)
{
    // the tet (cell centre, face base point, two face points) and its values,
    // as interpolationCellPoint takes them
    const triFace tri = tetIs.faceTriIs(mesh);
    const scalar v0 = cellValues[tetIs.cell()], v1 = pointValues[tri[0]],
        v2 = pointValues[tri[1]], v3 = pointValues[tri[2]];
    value = v0*c[0] + v1*c[1] + v2*c[2] + v3*c[3];
    // the linear function's gradient: (b - a, c - a, d - a) . g = dv
    const tetPointRef tet = tetIs.tet(mesh);
    const vector ba = tet.b() - tet.a(), ca = tet.c() - tet.a(),
        da = tet.d() - tet.a();
    const tensor M
    (
        ba.x(), ba.y(), ba.z(),
        ca.x(), ca.y(), ca.z(),
        da.x(), da.y(), da.z()
    );
    grad = Zero;
    if (mag(det(M)) > 1e-12*mag(ba)*mag(ca)*mag(da))
    {
        grad = inv(M) & vector(v1 - v0, v2 - v0, v3 - v0);
    }
}
