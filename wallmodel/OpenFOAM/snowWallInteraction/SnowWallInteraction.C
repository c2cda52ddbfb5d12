/*---------------------------------------------------------------------------*\
  SnowWall: wallmodel/OpenFOAM/snowWallInteraction
-------------------------------------------------------------------------------
Description
    SnowWallInteraction: set-up. The constructors and destructor; the set-up
    from snowWallInteractionCoeffs (the regimes, the gates, build-up, the snow
    patches and their counters, stick records, wallRegimes), with the
    dictionary's reading and checking in snowWallCoeffs.C; the start-up
    checks against the cloud's other sub-models (collision, surface film);
    the deposit field. The impacts are in SnowWallInteractionImpact.C, the
    log and the files in SnowWallInteractionIO.C (both included at the end).
    See SnowWallInteraction.H and doc/wallmodel.md.

\*---------------------------------------------------------------------------*/

#include "SnowWallInteraction.H"
#include "snowWallCoeffs.H"
#include "fvMesh.H"
#include "Time.H"
#include "wallPolyPatch.H"
#include "symmetryPlanePolyPatch.H"
#include "symmetryPolyPatch.H"
#include "regionModel.H"
#include "snowMachineLimits.H"
#include "snowTrackingStall.H"
#include "OStringStream.H"
#include <cmath>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{
namespace snowWallDetail
{

//- The cloud is a colliding one (KinematicCollidingCloud, which reads a
//  collisionModel): its parcels keep collision records. The model is
//  templated on the kinematic base cloud, so the parcel type tells;
//  overload resolution picks the first where the expression exists.
template<class P>
auto collidingParcel(const P* p, int) -> decltype(p->collisionRecords(), bool())
{
    return true;
}

template<class P>
bool collidingParcel(const P*, long)
{
    return false;
}

} // End namespace snowWallDetail
} // End namespace Foam


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
void Foam::SnowWallInteraction<CloudType>::noticeCollision() const
{
    typedef typename CloudType::parcelType parcelType;
    if (!snowWallDetail::collidingParcel(static_cast<const parcelType*>(nullptr), 0))
    {
        return;
    }
    const dictionary& sm = this->owner().subModelProperties();
    const word cm(sm.lookupOrDefault<word>("collisionModel", "none"));
    if (cm == "none")
    {
        return;
    }
    word wm("?");
    if (sm.isDict(cm + "Coeffs"))
    {
        wm = sm.subDict(cm + "Coeffs").lookupOrDefault<word>("wallModel", "?");
    }
    // pairCollision's wall model acts on the faces of wall-type patches
    // (InteractionLists: wallPolyPatch) only: a snow patch of another type
    // is decided as usual
    const polyBoundaryMesh& bm = this->owner().mesh().boundaryMesh();
    DynamicList<word> onWall, notWall;
    for (const label patchi : snowPatches_)
    {
        if (isA<wallPolyPatch>(bm[patchi])) onWall.append(bm[patchi].name());
        else notWall.append(bm[patchi].name());
    }
    OStringStream rest;
    if (notWall.size())
    {
        rest<< "; the snow patches " << notWall << " are not of type wall: "
            << "the collision model does not act there, their impacts are "
            << "decided as usual";
    }
    WarningInFunction
        << "snowWallInteraction: the cloud's collisionModel " << cm
        << " (wallModel " << wm << ") meets the walls first: it pushes a "
        << "parcel back before the parcel's centre reaches a wall face, so "
        << "on the snow patches of type wall " << onWall
        << " snowWallInteraction sees few or no impacts and decides none of "
        << "the others (no stick, no deposit from the contacts the collision "
        << "model handles)" << rest.str().c_str()
        << ". For the snow model to decide every wall impact set  "
        << "collisionModel none;  in subModels of "
        << snowWallCoeffs::dictFile(sm)
        << " (doc/wallmodel.md, \"Collision models\")" << endl;
}


template<class CloudType>
void Foam::SnowWallInteraction<CloudType>::checkFilm(const bool atSetup)
{
    const dictionary& sm = this->owner().subModelProperties();
    const word fm(sm.lookupOrDefault<word>("surfaceFilmModel", "none"));
    const objectRegistry& db = this->owner().mesh().time();
    const word regionName("surfaceFilmProperties");
    if (fm == "none")
    {
        filmChecked_ = true;
        return;
    }
    if (!db.foundObject<regionModels::regionModel>(regionName))
    {
        // the film region is made after the cloud (reactingParcelFoam):
        // checked again at the first impact or the end of the first step
        if (!atSetup)
        {
            filmChecked_ = true;
            WarningInFunction
                << "snowWallInteraction: the cloud's surfaceFilmModel " << fm
                << " found no film region (" << regionName << "): the snow "
                << "patches could not be checked against the film's" << endl;
        }
        return;
    }
    filmChecked_ = true;
    const regionModels::regionModel& film =
        db.lookupObject<regionModels::regionModel>(regionName);
    const polyBoundaryMesh& bm = this->owner().mesh().boundaryMesh();
    DynamicList<word> taken, left;
    for (const label patchi : snowPatches_)
    {
        if (film.isRegionPatch(patchi)) taken.append(bm[patchi].name());
        else left.append(bm[patchi].name());
    }
    if (taken.empty())
    {
        return;
    }
    word it("?");
    if (sm.isDict(fm + "Coeffs"))
    {
        it = sm.subDict(fm + "Coeffs").lookupOrDefault<word>("interactionType", "?");
    }
    const dictionary& cd = this->coeffDict();
    if (left.empty())
    {
        snowWallCoeffs::fatalAt(cd, cd.findEntry("patches", keyType::LITERAL))
            << "snowWallInteraction: every snow patch " << taken << " is a "
            << "patch of the surface film (" << film.type() << ", region "
            << film.regionMesh().name() << "): the cloud's surfaceFilmModel "
            << fm << " (interactionType " << it << ") takes every parcel that "
            << "hits it before the patch interaction model, so "
            << "snowWallInteraction would decide no impact and deposit "
            << "nothing. Give those patches type none (the film decides them) "
            << "or set  surfaceFilmModel none;  in subModels of "
            << snowWallCoeffs::dictFile(sm) << exit(FatalIOError);
    }
    WarningInFunction
        << "snowWallInteraction: the snow patches " << taken << " are "
        << "patches of the surface film (" << film.type() << ", region "
        << film.regionMesh().name() << "): the cloud's surfaceFilmModel " << fm
        << " (interactionType " << it << ") takes every parcel that hits them "
        << "before the patch interaction model (absorbed, splashed or bounced "
        << "by the film), so snowWallInteraction sees no impact there and "
        << "counts no stick or deposit on them; the snow patches " << left
        << " are decided as usual" << endl;
}


template<class CloudType>
void Foam::SnowWallInteraction<CloudType>::estimateStickRecords
(
    const dictionary& cd
) const
{
    label nRec = 0;
    forAll(recordSticks_, si)
    {
        if (recordSticks_[si]) ++nRec;
    }
    if (!nRec)
    {
        return;
    }
    const dictionary& props = this->owner().particleProperties();
    const scalar nInj = snowMachine::injectedParcels
    (
        this->owner().subModelProperties().subOrEmptyDict("injectionModels")
    );
    const scalar F =
        snowMachine::splitFactor(props.subOrEmptyDict("cloudFunctions"));
    // one record: time, position, origin processor and id, nParticle, d,
    // rho at the stream's precision: at most about 128 characters; held as
    // a std::string (plus about 32 bytes) until the next write, and twice on
    // the master while it gathers
    const scalar recDisk = 128, recMem = 2*(128 + 32);
    const Time& time = this->owner().mesh().time();
    const fileName dir(time.globalPath());
    const scalar freeB = snowMachine::freeDisk(dir);
    const scalar avail = snowMachine::memAvailable();
    const scalar MB = 1e6, GB = 1e9;
    Info<< "    snowWallInteraction: stickRecords: ";
    if (nInj < 0)
    {
        Info<< "the parcels injected cannot be told from the injection "
            << "models (manual, cell-zone or field-activated injection): "
            << "about " << recDisk << " bytes per stick on disk, "
            << (freeB >= 0 ? std::string(Foam::name(freeB/GB)) + " GB free" : std::string("free disk unknown")).c_str()
            << " in " << dir << endl;
        return;
    }
    const scalar nMax = snowMachine::parcelsBound(nInj, F);
    const scalar disk = nMax*recDisk + 1024*nRec;
    const scalar mem = nMax*recMem;
    Info<< "at most " << std::floor(nMax) << " sticks ("
        << std::floor(nInj) << " parcels injected";
    if (F > 1) Info<< ", split up to factor " << F << ": x (1 + 4F/3)";
    Info<< "; an upper bound: every parcel sticks) x " << recDisk
        << " bytes = " << disk/MB << " MB on disk, "
        << (freeB >= 0 ? std::string(Foam::name(freeB/GB)) + " GB free" : std::string("free disk unknown")).c_str()
        << "; at most " << mem/MB << " MB of memory between writes, "
        << (avail >= 0 ? std::string(Foam::name(avail/GB)) + " GB available" : std::string("available memory unknown")).c_str()
        << endl;
    const entry* e = cd.findEntry("stickRecords", keyType::LITERAL);
    if (freeB >= 0 && disk > freeB)
    {
        snowWallCoeffs::fatalAt(cd, e)
            << "snowWallInteraction: stickRecords: the records may need up to "
            << disk/MB << " MB (" << std::floor(nMax)
            << " sticks x " << recDisk << " bytes: every injected parcel"
            << (F > 1 ? " and split copy" : "") << " sticking once, an upper "
            << "bound), more than the " << freeB/MB << " MB free in " << dir
            << ": record fewer patches, inject fewer parcels or free disk"
            << exit(FatalIOError);
    }
    if (avail >= 0 && mem > 0.8*avail)
    {
        snowWallCoeffs::fatalAt(cd, e)
            << "snowWallInteraction: stickRecords: the records held between "
            << "writes may need up to " << mem/GB << " GB of memory ("
            << std::floor(nMax) << " sticks x " << recMem
            << " bytes, an upper bound), more than 80 % of the "
            << avail/GB << " GB available (MemAvailable of /proc/meminfo): "
            << "record fewer patches or write more often" << exit(FatalIOError);
    }
}


template<class CloudType>
void Foam::SnowWallInteraction<CloudType>::checkPatterns
(
    const wordRes& sel,
    const dictionary& dict,
    const string& what
) const
{
    const polyBoundaryMesh& bm = this->owner().mesh().boundaryMesh();
    forAll(sel, j)
    {
        bool hit = false;
        forAll(snowPatches_, si)
        {
            if (sel[j].match(bm[snowPatches_[si]].name())) hit = true;
        }
        if (!hit)
        {
            FatalIOErrorInFunction(dict)
                << "snowWallInteraction: " << what.c_str() << " '" << sel[j]
                << "' matches no snow patch" << exit(FatalIOError);
        }
    }
}


template<class CloudType>
void Foam::SnowWallInteraction<CloudType>::applyGates
(
    sww_model* m,
    const dictionary& cd
)
{
    snowWallCoeffs::applyGates
    (
        context_, m, cd, this->owner().mesh(), shearOn_, tauName_, rhoAir_
    );
}


template<class CloudType>
void Foam::SnowWallInteraction<CloudType>::setupWallRegimes
(
    const dictionary& cd
)
{
    // Every snow patch decides with the main regime unless a wallRegimes
    // entry selects it: that entry's regime, read and gated exactly as the
    // main one (readRegime, applyGates)
    const label n = snowPatches_.size();
    slotModel_.setSize(n, model_);
    if (!cd.found("wallRegimes"))
    {
        return;
    }
    const polyBoundaryMesh& bm = this->owner().mesh().boundaryMesh();
    const dictionary& wr = cd.subDict("wallRegimes");
    labelList owner(n, -1);
    for (const entry& e : wr)
    {
        const word name(e.keyword());
        if (!e.isDict())
        {
            FatalIOErrorInFunction(wr)
                << "snowWallInteraction: wallRegimes entry '" << name
                << "' is not a sub-dictionary { patches (...); #include "
                << "\"regime-....coeffs\" }" << exit(FatalIOError);
        }
        const dictionary& ed = e.dict();
        if (!ed.found("patches"))
        {
            FatalIOErrorInFunction(ed)
                << "snowWallInteraction: wallRegimes entry '" << name
                << "': missing 'patches' (the snow patches it applies to)"
                << exit(FatalIOError);
        }
        if (!ed.isDict("regime"))
        {
            FatalIOErrorInFunction(ed)
                << "snowWallInteraction: wallRegimes entry '" << name
                << "': missing sub-dictionary 'regime': add  #include "
                << "\"regime-....coeffs\"  (written by snowregime map)"
                << exit(FatalIOError);
        }
        const wordRes sel(ed.get<wordRes>("patches"));
        snowWallCoeffs::checkNotEmpty
        (
            ed, sel, "wallRegimes entry '" + std::string(name) + "'"
        );

        const label k = patchModels_.size();
        sww_model* m = sww_alloc();
        if (!m)
        {
            FatalErrorInFunction << "out of memory" << exit(FatalError);
        }
        patchModels_.append(m);
        patchModelNames_.append(name);
        context_ = "wallRegimes " + name + ": ";
        snowWallCoeffs::readRegime(context_, m, ed.subDict("regime"));
        applyGates(m, cd);
        context_.clear();

        checkPatterns
        (
            sel, ed, "wallRegimes entry '" + name + "': patch pattern"
        );
        Info<< "    snowWallInteraction: wallRegimes " << name << ": patches";
        forAll(snowPatches_, si)
        {
            const word& pn = bm[snowPatches_[si]].name();
            if (!sel.match(pn)) continue;
            if (owner[si] >= 0)
            {
                FatalIOErrorInFunction(wr)
                    << "snowWallInteraction: snow patch " << pn << " is "
                    << "matched by two wallRegimes entries, '"
                    << patchModelNames_[owner[si]] << "' and '" << name
                    << "': a patch takes one regime" << exit(FatalIOError);
            }
            owner[si] = k;
            slotModel_[si] = m;
            Info<< ' ' << pn;
        }
        // the description names a stick-probability table (rough wall)
        char desc[1024];
        sww_describe(m, desc, sizeof desc);
        Info<< "; regime " << desc << endl;
    }
    Info<< "    snowWallInteraction: main regime on the snow patches";
    forAll(snowPatches_, si)
    {
        if (owner[si] < 0) Info<< ' ' << bm[snowPatches_[si]].name();
    }
    Info<< endl;
}


template<class CloudType>
void Foam::SnowWallInteraction<CloudType>::setupBuildUp(const dictionary& cd)
{
    // Build-up feedback: a face covered by its own deposit decides with the
    // snow-covered regime (doc/wallmodel.md)
    if (cd.isDict("buildUp"))
    {
        const dictionary& b = cd.subDict("buildUp");
        if (b.lookupOrDefault<Switch>("active", true))
        {
            if (!b.isDict("regime"))
            {
                FatalIOErrorInFunction(b)
                    << "snowWallInteraction: buildUp: missing sub-dictionary "
                    << "'regime': add  #include \"regime-snow.coeffs\"  (written "
                    << "by snowregime map --config regime/configs/ice-on-ice.conf)"
                    << exit(FatalIOError);
            }
            covered_ = sww_alloc();
            if (!covered_)
            {
                FatalErrorInFunction << "out of memory" << exit(FatalError);
            }
            snowWallCoeffs::readRegime(context_, covered_, b.subDict("regime"));
            applyGates(covered_, cd);
            scalar dCover = -1;
            coverMass_ = snowWallCoeffs::coverMass
            (
                b, this->owner().constProps().rho0(), dCover
            );
            char desc[1024];
            sww_describe(covered_, desc, sizeof desc);
            Info<< "    snowWallInteraction: build-up on: snow-covered regime "
                << desc << nl << "    covering mass " << coverMass_ << " kg/m2";
            if (dCover > 0)
            {
                Info<< " (one monolayer of " << dCover
                    << " m spheres: 0.6046 rho d)";
            }
            Info<< "; a face blends bare and covered with w = min(1, deposit/"
                << "covering mass)" << endl;
        }
    }
}


template<class CloudType>
void Foam::SnowWallInteraction<CloudType>::setupSnowPatches(const dictionary& cd)
{
    // Interaction type of every patch group: OpenFOAM's own for none,
    // rebound, stick and escape (PatchInteractionModel::interactionType, as
    // localInteraction); snow is the one other type (itOther) accepted
    groupType_.setSize(patchData_.size());
    forAll(patchData_, groupi)
    {
        const word& t = patchData_[groupi].interactionTypeName();
        groupType_[groupi] = this->wordToInteractionType(t);
        if (groupType_[groupi] == itSnow && t != "snow")
        {
            FatalIOErrorInFunction(cd)
                << "snowWallInteraction: patch " << patchData_[groupi].patchName()
                << ": type '" << t << "' is not snow, rebound, stick, escape "
                << "or none" << exit(FatalIOError);
        }
    }

    // Snow patches and their totals (cumulative, restored on restart)
    const polyBoundaryMesh& bm = this->owner().mesh().boundaryMesh();
    openPatch_.setSize(bm.size(), false);
    slotOfPatch_.setSize(bm.size(), -1);
    groupOfPatch_.setSize(bm.size(), -1);
    DynamicList<label> snow;
    forAll(bm, patchi)
    {
        openPatch_[patchi] =
            !isA<wallPolyPatch>(bm[patchi])
         && !polyPatch::constraintType(bm[patchi].type());
        const label groupi = patchData_.applyToPatch(patchi);
        groupOfPatch_[patchi] = groupi;
        if (groupi >= 0 && groupType_[groupi] == itSnow)
        {
            if (!isA<wallPolyPatch>(bm[patchi]))
            {
                WarningInFunction
                    << "snowWallInteraction: snow patch " << bm[patchi].name()
                    << " is of type " << bm[patchi].type() << ", not wall: "
                    << "its impacts are decided as on a wall, but a fixed "
                    << "flow velocity on it is not taken as the wall's"
                    << endl;
            }
            slotOfPatch_[patchi] = snow.size();
            snow.append(patchi);
        }
    }
    snowPatches_.transfer(snow);
}


template<class CloudType>
void Foam::SnowWallInteraction<CloudType>::setupBuildUpPatches(const dictionary& cd)
{
    const polyBoundaryMesh& bm = this->owner().mesh().boundaryMesh();
    const label n = snowPatches_.size();

    // the snow patches with the build-up feedback: buildUp/patches, or all
    buildUpOn_.setSize(n, covered_ != nullptr);
    if (covered_ && cd.subDict("buildUp").found("patches"))
    {
        const dictionary& b = cd.subDict("buildUp");
        const wordRes sel(b.get<wordRes>("patches"));
        snowWallCoeffs::checkNotEmpty(b, sel, "buildUp");
        checkPatterns(sel, b, "buildUp patches:");
        forAll(snowPatches_, si)
        {
            buildUpOn_[si] = sel.match(bm[snowPatches_[si]].name());
        }
        Info<< "    snowWallInteraction: build-up on the snow patches";
        forAll(snowPatches_, si)
        {
            if (buildUpOn_[si]) Info<< ' ' << bm[snowPatches_[si]].name();
        }
        Info<< endl;
    }
}


template<class CloudType>
void Foam::SnowWallInteraction<CloudType>::setupStickRecords(const dictionary& cd)
{
    const polyBoundaryMesh& bm = this->owner().mesh().boundaryMesh();
    const label n = snowPatches_.size();

    // the snow patches whose sticks are recorded: stickRecords, or none
    recordSticks_.setSize(n, false);
    stickLines_.setSize(n);
    if (cd.found("stickRecords"))
    {
        const wordRes sel(cd.get<wordRes>("stickRecords"));
        if (sel.empty())
        {
            snowWallCoeffs::fatalAt(cd, cd.findEntry("stickRecords", keyType::LITERAL))
                << "snowWallInteraction: stickRecords: the list is empty (give "
                << "at least one snow patch name or pattern, or leave the entry out)"
                << exit(FatalIOError);
        }
        checkPatterns(sel, cd, "stickRecords:");
        Info<< "    snowWallInteraction: sticks recorded on";
        forAll(snowPatches_, si)
        {
            recordSticks_[si] = sel.match(bm[snowPatches_[si]].name());
            if (recordSticks_[si]) Info<< ' ' << bm[snowPatches_[si]].name();
        }
        Info<< " (postProcessing/lagrangian/" << this->owner().name()
            << "/snowWallSticks)" << endl;
        estimateStickRecords(cd);
    }
}


template<class CloudType>
void Foam::SnowWallInteraction<CloudType>::setupCounts()
{
    const polyBoundaryMesh& bm = this->owner().mesh().boundaryMesh();
    const label n = snowPatches_.size();

    // the counts of this run and the totals at the start time (restart)
    nImpact_.setSize(n, 0);
    nStick_.setSize(n, 0);
    nBounce_.setSize(n, 0);
    nRipoff_.setSize(n, 0);
    nOutside_.setSize(n, 0);
    massDeposit_.setSize(n, 0.0);
    nImpact0_.setSize(n, 0);
    nStick0_.setSize(n, 0);
    nBounce0_.setSize(n, 0);
    nRipoff0_.setSize(n, 0);
    nOutside0_.setSize(n, 0);
    massDeposit0_.setSize(n, 0.0);
    forAll(snowPatches_, s)
    {
        const word& pn = bm[snowPatches_[s]].name();
        this->getModelProperty(pn + ":impacts", nImpact0_[s]);
        this->getModelProperty(pn + ":sticks", nStick0_[s]);
        this->getModelProperty(pn + ":bounces", nBounce0_[s]);
        this->getModelProperty(pn + ":ripoffs", nRipoff0_[s]);
        this->getModelProperty(pn + ":outsideFitRange", nOutside0_[s]);
        this->getModelProperty(pn + ":depositedMass", massDeposit0_[s]);
    }

    // Counts by reason: the snow patches, then where parcels escape
    {
        DynamicList<label> rep(snowPatches_);
        forAll(bm, patchi)
        {
            const label g = groupOfPatch_[patchi];
            if
            (
                g >= 0
             && (
                    groupType_[g] == PatchInteractionModel<CloudType>::itEscape
                 || (
                        groupType_[g] == PatchInteractionModel<CloudType>::itNone
                     && openPatch_[patchi]
                    )
                )
            )
            {
                rep.append(patchi);
            }
        }
        reportPatches_.transfer(rep);
    }
    const label nc = SWW_NCLASS + 1;
    reportOfPatch_.setSize(bm.size(), -1);
    nReason_.setSize(nc*reportPatches_.size(), 0);
    nReason0_.setSize(nc*reportPatches_.size(), 0);
    forAll(reportPatches_, r)
    {
        reportOfPatch_[reportPatches_[r]] = r;
        // a case written without the counts by reason (by an older version
        // of this model) restarts them here, from zero
        labelList c0;
        this->getModelProperty(bm[reportPatches_[r]].name() + ":byReason", c0);
        if (c0.size() == nc)
        {
            forAll(c0, c)
            {
                nReason0_[nc*r + c] = c0[c];
            }
        }
    }
}


template<class CloudType>
void Foam::SnowWallInteraction<CloudType>::setup()
{
    const dictionary& cd = this->coeffDict();
    model_ = sww_alloc();
    if (!model_)
    {
        FatalErrorInFunction << "out of memory" << exit(FatalError);
    }

    if (!cd.isDict("regime"))
    {
        FatalIOErrorInFunction(cd)
            << "snowWallInteraction: missing sub-dictionary 'regime' in "
            << cd.name() << ": add  #include \"regime.coeffs\"  (written by "
            << "snowregime map) to snowWallInteractionCoeffs"
            << exit(FatalIOError);
    }
    snowWallCoeffs::readRegime(context_, model_, cd.subDict("regime"));

    removeStuck_ = snowWallCoeffs::removeStuckParcels(cd);

    applyGates(model_, cd);

    setupBuildUp(cd);
    setupSnowPatches(cd);
    setupBuildUpPatches(cd);
    setupStickRecords(cd);
    setupWallRegimes(cd);
    {
        seed_ = snowWallCoeffs::randomSeed(cd);
        drawMatters_ = covered_ != nullptr;
        forAll(slotModel_, si)
        {
            if (sww_probability_table(slotModel_[si], nullptr, nullptr)) drawMatters_ = true;
        }
    }
    setupCounts();

    const polyBoundaryMesh& bm = this->owner().mesh().boundaryMesh();
    char desc[1024];
    sww_describe(model_, desc, sizeof desc);
    Info<< "    snowWallInteraction: regime " << desc << nl
        << "    snow patches:";
    for (const label patchi : snowPatches_)
    {
        Info<< ' ' << bm[patchi].name();
    }
    Info<< nl << "    stuck parcels: " << (removeStuck_ ? "removed" : "kept")
        << ", deposit field " << this->owner().name() << ":snowDeposit"
        << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::SnowWallInteraction<CloudType>::SnowWallInteraction
(
    const dictionary& dict,
    CloudType& cloud
)
:
    PatchInteractionModel<CloudType>(dict, cloud, typeName),
    patchData_
    (
        cloud.mesh(),
        snowWallCoeffs::checkedPatches(cloud.mesh(), this->coeffDict())
    ),
    groupType_(),
    model_(nullptr),
    patchModels_(),
    patchModelNames_(),
    slotModel_(),
    context_(),
    covered_(nullptr),
    coverMass_(-1),
    removeStuck_(true),
    shearOn_(false),
    tauName_("wallShearStress"),
    rhoAir_(-1),
    seed_(1234567),
    drawMatters_(false),
    drawStep_(-1),
    drawsInStep_(),
    openPatch_(),
    slotOfPatch_(),
    snowPatches_(),
    depositPtr_(nullptr),
    seriesPtr_(nullptr),
    filmChecked_(false)
{
    setup();
    noticeCollision();
    checkFilm(true);
    (void)deposit();
}


template<class CloudType>
Foam::SnowWallInteraction<CloudType>::SnowWallInteraction
(
    const SnowWallInteraction<CloudType>& pim
)
:
    PatchInteractionModel<CloudType>(pim),
    patchData_(pim.patchData_),
    groupType_(),
    model_(nullptr),
    patchModels_(),
    patchModelNames_(),
    slotModel_(),
    context_(),
    covered_(nullptr),
    coverMass_(-1),
    removeStuck_(true),
    shearOn_(false),
    tauName_("wallShearStress"),
    rhoAir_(-1),
    seed_(pim.seed_),
    drawMatters_(false),
    drawStep_(-1),
    drawsInStep_(),
    openPatch_(),
    slotOfPatch_(),
    snowPatches_(),
    depositPtr_(nullptr),
    seriesPtr_(nullptr),
    filmChecked_(pim.filmChecked_)
{
    setup();
    nImpact_ = pim.nImpact_;
    nStick_ = pim.nStick_;
    nBounce_ = pim.nBounce_;
    nRipoff_ = pim.nRipoff_;
    nOutside_ = pim.nOutside_;
    massDeposit_ = pim.massDeposit_;
    nImpact0_ = pim.nImpact0_;
    nStick0_ = pim.nStick0_;
    nBounce0_ = pim.nBounce0_;
    nRipoff0_ = pim.nRipoff0_;
    nOutside0_ = pim.nOutside0_;
    massDeposit0_ = pim.massDeposit0_;
    nReason_ = pim.nReason_;
    nReason0_ = pim.nReason0_;
    stickLines_ = pim.stickLines_;
    if (pim.depositPtr_.valid())
    {
        // an unregistered copy: the original owns the registered field
        const volScalarField& d0 = pim.depositPtr_();
        depositPtr_.reset
        (
            new volScalarField
            (
                IOobject
                (
                    d0.name() + ":copy", d0.instance(), d0.db(),
                    IOobject::NO_READ, IOobject::NO_WRITE, false
                ),
                d0
            )
        );
    }
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

template<class CloudType>
Foam::SnowWallInteraction<CloudType>::~SnowWallInteraction()
{
    sww_free(model_);
    for (sww_model* m : patchModels_)
    {
        sww_free(m);
    }
    sww_free(covered_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::volScalarField& Foam::SnowWallInteraction<CloudType>::deposit()
{
    if (!depositPtr_.valid())
    {
        const fvMesh& mesh = this->owner().mesh();
        depositPtr_.reset
        (
            new volScalarField
            (
                IOobject
                (
                    this->owner().name() + ":snowDeposit",
                    mesh.time().timeName(),
                    mesh,
                    IOobject::READ_IF_PRESENT,
                    IOobject::AUTO_WRITE
                ),
                mesh,
                dimensionedScalar(dimMass/dimArea, Zero)
            )
        );
    }
    return depositPtr_();
}



// * * * * * * * * * * * * * * * * Impacts, output  * * * * * * * * * * * * * //

#include "SnowWallInteractionImpact.C"
#include "SnowWallInteractionIO.C"

// ************************************************************************* //
