/*---------------------------------------------------------------------------*\
  SnowWall: wallmodel/OpenFOAM/wellMixedCheck/snowWallLayer.C (see the .H)
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
