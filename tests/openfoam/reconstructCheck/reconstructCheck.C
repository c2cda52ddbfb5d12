/*---------------------------------------------------------------------------*\
reconstructCheck - how well fvc::reconstruct, compiled in this program's own
translation unit, gives back a uniform vector from its face fluxes.

For any mesh fvc::reconstruct(Sf & U0) = inv(sum(SfHat Sf)) & sum(SfHat (Sf & U0))
is U0 in every cell to round-off. With GCC 12 at -O3 the inner product
inv(tmp) & tmp writes its result into its second argument's storage while
OpenFOAM's loop macros declare both pointers __restrict__: the x component of a
cell's result can overwrite the input before its y and z components read it.
Built twice by tests/openfoam/reconstructCheck/run.sh, with and without
-D__restrict__=, it prints for the case's mesh the cells whose result is off by
more than 1e-9 |U0| and the largest error, so the two builds can be compared.

Usage (in a case folder): reconstructCheck
\*---------------------------------------------------------------------------*/

#include "fvCFD.H"

int main(int argc, char *argv[])
{
    argList::noParallel();
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    const vector U0(1, 2, 3);
    const surfaceScalarField flux
    (
        "flux",
        mesh.Sf() & dimensionedVector("U0", dimVelocity, U0)
    );
    const volVectorField rec(fvc::reconstruct(flux));

    const scalarField err(mag(rec.primitiveField() - U0));
    label nBad = 0;
    forAll(err, celli)
    {
        if (err[celli] > 1e-9*mag(U0)) ++nBad;
    }
    // the largest error of each component: which ones the overwrite reaches
    vector maxComp(Zero);
    forAll(err, celli)
    {
        const vector d(rec.primitiveField()[celli] - U0);
        for (direction i = 0; i < vector::nComponents; ++i)
        {
            maxComp[i] = max(maxComp[i], mag(d[i]));
        }
    }
    Info<< "reconstructCheck: cells " << mesh.nCells()
        << ", off by more than 1e-9 |U0|: " << nBad
        << ", max |error| / |U0|: " << max(err)/mag(U0)
        << ", per component x y z: " << maxComp[0]/mag(U0) << ' '
        << maxComp[1]/mag(U0) << ' ' << maxComp[2]/mag(U0) << endl;
    return 0;
}
