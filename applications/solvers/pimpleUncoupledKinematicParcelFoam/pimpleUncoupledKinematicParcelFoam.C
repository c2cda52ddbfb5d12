/*---------------------------------------------------------------------------*\
  SnowWall: applications/solvers/pimpleUncoupledKinematicParcelFoam
-------------------------------------------------------------------------------
Application
    pimpleUncoupledKinematicParcelFoam

Description
    Transient incompressible turbulent flow (PIMPLE, any RAS/LES/DES model of
    the incompressible turbulence library, fvOptions) with a kinematic
    particle cloud that moves through the flow of every time step, one-way
    coupled: the particles feel the flow, the flow does not feel them.

    It is OpenFOAM's pimpleFoam time loop on a static mesh with one added
    step: after the flow of a time step has converged, the cloud is evolved
    over that same step in the new velocity field, exactly as
    icoUncoupledKinematicParcelFoam evolves it in a frozen one. The flow
    equations are pimpleFoam's own (createFields.H, UEqn.H, pEqn.H of the
    OpenFOAM v1912 source, included at build time, not copied); the cloud is
    the library's basicKinematicCloud, so every stock sub-model and any
    patch interaction model registered for it (snowWallInteraction) is
    selectable at run time in <cloud>Properties.

    Several independent clouds can ride the same flow (-clouds): each reads
    its own constant/<name>Properties, e.g. the same spray with different
    wall-interaction settings, so a comparison costs one flow solution.

    With -frozen the flow is not solved: the fields of the start time (a
    converged steady flow, say) are held, and the time loop only evolves
    the clouds, as icoUncoupledKinematicParcelFoam does for one cloud.

    With -frozen -speedScale S the held flow is first scaled to S times its
    speed at the same geometry: U, phi and the turbulence velocity scales
    by S, and every field of the list below by S^-n where n is the time
    exponent of its dimensions (p, k by S^2, omega, nut by S, epsilon by
    S^3), boundary values included. This is the flow at S times the speed
    with S times the viscosity (the same Reynolds number, exactly); read as
    the flow at S times the speed in the same air, it assumes the mean flow
    does not depend on the Reynolds number between the two. The cloud's
    viscosity stays transportProperties' nu.

    With -replay the flow is solved until a library of snapshots is
    complete (controlDict sub-dictionary replay: start, period, interval,
    fields), then played back periodically while the clouds go on moving
    (flowReplay.H): the clouds can be carried for longer than the flow is
    solved, at the cost of the particles alone.

    Required: the pimpleFoam fields (U, p, turbulence fields),
    transportProperties with nu and rhoInf (the carrier density seen by the
    cloud), constant/g and <cloud>Properties.

    With -checkpoint S a time step becomes a write time (everything written
    as at the controlDict's writes: fields, clouds, model properties, the
    function objects' writes) whenever S seconds of wall clock have passed
    since the last write, without changing the time steps: a run of hours
    leaves a state to resume from (startFrom latestTime; with -replay the
    library must be stored, flowReplay.H) at least every S seconds.

Usage
    pimpleUncoupledKinematicParcelFoam [-cloud NAME | -clouds '(NAME ...)']
                                       [-frozen [-speedScale S] | -replay]
                                       [-checkpoint S]
                                       [-parallel] [-help]

    -cloud NAME         the cloud (default kinematicCloud)
    -clouds '(A B ..)'  several clouds, evolved one after the other in every
                        time step, each from constant/<name>Properties

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "singlePhaseTransportModel.H"
#include "turbulentTransportModel.H"
#include "pimpleControl.H"
#include "fvOptions.H"
#include "basicKinematicCloud.H"
#include "flowReplay.H"
#include <cfenv>
#include <chrono>
#include <cstdlib>
#include <string>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

//- Wall clock of the flow and of every cloud
typedef std::chrono::steady_clock wallClock;

//- The seconds of wall clock since t0
double secondsSince(const wallClock::time_point& t0)
{
    return std::chrono::duration<double>(wallClock::now() - t0).count();
}


//- The note and the options of the solver (-cloud, -clouds, -frozen,
//  -speedScale, -replay, -checkpoint)
void addOptions()
{
    argList::addNote
    (
        "Transient incompressible turbulent flow (PIMPLE) with a one-way"
        " coupled kinematic particle cloud evolved in the flow of every"
        " time step"
    );
    argList::addOption
    (
        "cloud",
        "name",
        "specify alternative cloud name. default is 'kinematicCloud'"
    );
    argList::addOption
    (
        "clouds",
        "(name ...)",
        "several clouds in the same flow, each from constant/<name>Properties"
    );

    argList::addBoolOption
    (
        "frozen",
        "hold the flow of the start time: evolve the clouds only"
    );
    argList::addOption
    (
        "speedScale",
        "factor",
        "with -frozen: the held flow scaled to this many times its speed"
        " (U, phi by S; p, k by S^2; omega, nut by S; epsilon by S^3)"
    );
    argList::addBoolOption
    (
        "replay",
        "solve the flow until the snapshot library of the controlDict's"
        " 'replay' dictionary is complete, then play it back periodically"
    );

    argList::addOption
    (
        "checkpoint",
        "seconds",
        "also write when this many seconds of wall clock have passed since"
        " the last write (a state to resume from; the steps unchanged)"
    );
}


//- A positive finite number given as text: a nan must not reach a
//  comparison (the floating-point traps OpenFOAM sets would kill the run
//  without a word); false if the text is not one
bool positiveNumber(const std::string& txt, scalar& out)
{
    // strtod in non-stop mode: an overflowing text (1e999) must not
    // raise the overflow trap OpenFOAM has set; it is refused below
    char* end = nullptr;
    std::fenv_t env;
    std::feholdexcept(&env);
    const double v = std::strtod(txt.c_str(), &end);
    std::feclearexcept(FE_ALL_EXCEPT);
    std::fesetenv(&env);
    const bool whole = !txt.empty() && end && *end == '\0';
    if (!whole || !std::isfinite(v) || v <= 0)
    {
        return false;
    }
    out = v;
    return true;
}


//- -checkpoint: a positive finite number of seconds (wall clock), 0 when not
//  given
scalar checkpointOption(const argList& args)
{
    scalar checkpoint = 0;
    if (args.found("checkpoint"))
    {
        if (!positiveNumber(args["checkpoint"], checkpoint))
        {
            FatalErrorInFunction
                << "-checkpoint: a positive number of seconds of wall clock, "
                << "got " << args["checkpoint"].c_str() << exit(FatalError);
        }
        Info<< "Checkpoint: a write whenever " << checkpoint << " s of wall "
            << "clock have passed since the last one" << nl << endl;
    }
    return checkpoint;
}


//- -speedScale: with -frozen only, a factor in [1e-3, 1e3], 1 when not given
scalar speedScaleOption(const argList& args)
{
    scalar speedScale = 1;
    if (args.found("speedScale"))
    {
        if
        (
            !positiveNumber(args["speedScale"], speedScale)
         || speedScale < 1e-3 || speedScale > 1e3
        )
        {
            FatalErrorInFunction
                << "-speedScale: a factor from 0.001 to 1000, got "
                << args["speedScale"].c_str() << exit(FatalError);
        }
        if (!args.found("frozen"))
        {
            FatalErrorInFunction
                << "-speedScale scales the held flow: give -frozen too"
                << exit(FatalError);
        }
    }
    return speedScale;
}


//- The held flow at speedScale times its speed: each field read from the
//  start time by speedScale^-n, n its dimensions' time exponent
void scaleHeldFlow
(
    const scalar speedScale,
    const fvMesh& mesh,
    volVectorField& U,
    surfaceScalarField& phi,
    volScalarField& p
)
{
    const auto factor = [&](const dimensionSet& d)
    {
        return Foam::pow(speedScale, -d[dimensionSet::TIME]);
    };
    U == factor(U.dimensions())*U;
    phi == factor(phi.dimensions())*phi;
    p == factor(p.dimensions())*p;
    for (const word name : {"k", "omega", "epsilon", "nut", "nuTilda"})
    {
        if (mesh.foundObject<volScalarField>(name))
        {
            volScalarField& f = mesh.lookupObjectRef<volScalarField>(name);
            const scalar c = factor(f.dimensions());
            f == c*f;
            Info<< "Frozen flow: " << name << " x " << c << nl;
        }
    }
    Info<< "Frozen flow: U, phi x " << speedScale << ", p x "
        << factor(p.dimensions()) << " (-speedScale)" << nl << endl;
}


//- -replay: the snapshot library of the controlDict's 'replay' dictionary
//  (null without -replay); -frozen and -replay exclude each other
autoPtr<flowReplay> replayOption
(
    const argList& args,
    const fvMesh& mesh,
    const Time& runTime,
    const bool adjustTimeStep,
    const scalar maxDeltaT
)
{
    if (args.found("frozen") && args.found("replay"))
    {
        FatalErrorInFunction
            << "-frozen and -replay exclude each other" << exit(FatalError);
    }
    autoPtr<flowReplay> replay;
    if (args.found("replay"))
    {
        replay.reset
        (
            new flowReplay
            (
                mesh,
                runTime.controlDict().subDict("replay"),
                runTime.startTime().value(),
                adjustTimeStep,
                maxDeltaT,
                runTime.deltaTValue()
            )
        );
    }
    return replay;
}


//- Every cloud evolved over the time step, its wall-clock time added to
//  cloudTime
void evolveClouds
(
    PtrList<basicKinematicCloud>& kinematicClouds,
    scalarList& cloudTime
)
{
    forAll(kinematicClouds, ci)
    {
        basicKinematicCloud& kinematicCloud = kinematicClouds[ci];
        Info<< "Evolving " << kinematicCloud.name() << endl;

        const auto tCloud = wallClock::now();
        kinematicCloud.evolve();
        cloudTime[ci] += secondsSince(tCloud);
    }
}


//- The wall-clock time of the flow and of every cloud, summed over the
//  steps: the largest of the processes (the cost of each part, e.g. for the
//  error against run time)
void printWallTimes
(
    const scalar flowTime,
    const scalarList& cloudTime,
    const PtrList<basicKinematicCloud>& kinematicClouds
)
{
    Info<< "Wall time [s], largest of the processes: flow "
        << returnReduce(flowTime, maxOp<scalar>());
    forAll(kinematicClouds, ci)
    {
        Info<< ", " << kinematicClouds[ci].name() << ' '
            << returnReduce(cloudTime[ci], maxOp<scalar>());
    }
    Info<< endl;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    addOptions();

    #include "postProcess.H"

    #include "addCheckCaseOptions.H"
    #include "setRootCaseLists.H"

    const scalar checkpoint = checkpointOption(args);
    const scalar speedScale = speedScaleOption(args);

    #include "createTime.H"
    #include "createMesh.H"
    #include "createPimpleControl.H"
    #include "createTimeControls.H"
    #include "initContinuityErrs.H"
    #include "createFields.H"          // pimpleFoam's: p, U, phi, turbulence
    #include "createUfIfPresent.H"     // null on a static mesh
    #include "createCloudFields.H"     // rho, mu, g and the cloud
    #include "CourantNo.H"
    #include "setInitialDeltaT.H"

    if (speedScale != 1)
    {
        scaleHeldFlow(speedScale, mesh, U, phi, p);
    }

    turbulence->validate();

    const bool frozen = args.found("frozen");
    autoPtr<flowReplay> replay
    (
        replayOption(args, mesh, runTime, adjustTimeStep, maxDeltaT)
    );
    if (frozen)
    {
        Info<< "Frozen flow: the fields of time " << runTime.timeName()
            << " are held; only the clouds are evolved" << nl << endl;
    }

    // * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

    // wall-clock time of the flow and of every cloud, summed over the steps
    // (printed at each write and at the end)
    scalar flowTime = 0;
    scalarList cloudTime(kinematicClouds.size(), Zero);

    auto lastWrite = wallClock::now();

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        #include "readTimeControls.H"
        #include "CourantNo.H"
        #include "setDeltaT.H"

        // a checkpoint: the coming step becomes a write time (decided alike on
        // every process: the clocks differ)
        if
        (
            checkpoint > 0
         && returnReduce(secondsSince(lastWrite) >= checkpoint, orOp<bool>())
        )
        {
            runTime.writeOnce();
            Info<< "Checkpoint: " << checkpoint << " s of wall clock since "
                << "the last write: this step is written" << nl << endl;
        }

        ++runTime;

        Info<< "Time = " << runTime.timeName() << nl << endl;

        const auto tFlow = wallClock::now();

        // --- The flow: played back from the library once it is complete
        const bool replayed =
            replay.valid() && replay->replaying(runTime.value());
        if (replayed)
        {
            replay->set(runTime.value(), phi);
        }

        // --- The flow: pimpleFoam's pressure-velocity PIMPLE loop
        while (!frozen && !replayed && pimple.loop())
        {
            #include "UEqn.H"

            while (pimple.correct())
            {
                #include "pEqn.H"
            }

            if (pimple.turbCorr())
            {
                laminarTransport.correct();
                turbulence->correct();
            }
        }

        if (replay.valid() && !replayed)
        {
            replay->collect(runTime.value(), runTime.deltaTValue());
        }
        flowTime += secondsSince(tFlow);

        // --- The particles: the same time step, in the flow just computed
        mu = laminarTransport.nu()*rhoInfValue;

        evolveClouds(kinematicClouds, cloudTime);

        if (runTime.write())
        {
            printWallTimes(flowTime, cloudTime, kinematicClouds);
            lastWrite = wallClock::now();
        }

        runTime.printExecutionTime(Info);
    }

    printWallTimes(flowTime, cloudTime, kinematicClouds);

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //