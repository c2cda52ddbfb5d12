/*---------------------------------------------------------------------------*\
  SnowWall: wallmodel/OpenFOAM/snowNearWall/snowTrackingStall.C (see the .H)
\*---------------------------------------------------------------------------*/
#include "snowTrackingStall.H"

namespace
{
    // the first stall of a run is named, the others counted
    bool stallNoted = false;
}

bool Foam::snowTrackingStall
(
    swf_stall& guard,
    particle& p,
    const char* model,
    const word& name
)
{
    if (!swf_stall_check(&guard, &p, p.stepFraction()))
    {
        return false;
    }
    if (!stallNoted)
    {
        stallNoted = true;
        WarningInFunction
            << model << (name.empty() ? "" : " ") << name.c_str()
            << ": a parcel at " << p.position() << " in cell "
            << p.cell() << " (face " << p.face() << ") advanced its time step"
            << " by less than " << SWF_STALL_ADVANCE << " over "
            << SWF_STALL_CALLS << " tracking sub-steps or wall hits (a loop"
            << " at a wall that does not move it); its step is ended there"
            << " and the next starts from it. Further such steps are counted"
            << " in the model's summary (noted once per run)" << endl;
    }
    p.stepFraction() = 1;
    return true;
}


Foam::label Foam::snowStallCount(const swf_stall& guard)
{
    return returnReduce(label(guard.ended), sumOp<label>());
}
