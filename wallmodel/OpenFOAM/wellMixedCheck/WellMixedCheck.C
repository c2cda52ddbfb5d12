/*---------------------------------------------------------------------------*\
  SnowWall: wallmodel/OpenFOAM/wellMixedCheck (see WellMixedCheck.H)
\*---------------------------------------------------------------------------*/

#include "WellMixedCheck.H"
#include "snowWallLayer.H"
#include "snowTrackingStall.H"
#include "turbulenceModel.H"
#include "polyMeshTetDecomposition.H"
#include "OFstream.H"
#include "Pstream.H"
#include "OSspecific.H"

#include "swd.h"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
void Foam::WellMixedCheck<CloudType>::readSettings(const dictionary& dict)
{
    const wordList known
    ({
        "type", "patches", "bands", "zones", "startTime", "samplesPerCell",
        "totalSamples", "Cmu"
    });
    for (const entry& e : dict)
    {
        if (!known.found(e.keyword()))
        {
            FatalIOErrorInFunction(dict)
                << "wellMixedCheck: unknown key '" << e.keyword()
                << "' (known: " << known << ")" << exit(FatalIOError);
        }
    }
    patches_ = snowWallPatches
    (
        this->owner().mesh().boundaryMesh(), dict, "wellMixedCheck"
    );

    edges_ = dict.lookupOrDefault<scalarList>
    (
        "bands", scalarList({0, 1, 5, 30, 100})
    );
    if (edges_.size() < 1 || edges_[0] != 0)
    {
        FatalIOErrorInFunction(dict)
            << "wellMixedCheck: bands " << edges_ << " must start at 0"
            << exit(FatalIOError);
    }
    for (label i = 1; i < edges_.size(); ++i)
    {
        if (!(edges_[i] > edges_[i-1]) || !std::isfinite(edges_[i]))
        {
            FatalIOErrorInFunction(dict)
                << "wellMixedCheck: bands " << edges_ << ": " << edges_[i]
                << " does not follow " << edges_[i-1]
                << " (finite, strictly increasing)" << exit(FatalIOError);
        }
    }

    const fvMesh& mesh = this->owner().mesh();
    zoneNames_ = dict.lookupOrDefault<wordList>("zones", wordList());
    cellZones_.setSize(mesh.nCells());
    forAll(zoneNames_, z)
    {
        const label zi = mesh.cellZones().findZoneID(zoneNames_[z]);
        if (zi < 0)
        {
            FatalIOErrorInFunction(dict)
                << "wellMixedCheck: zones: no cell zone '" << zoneNames_[z]
                << "' (cell zones: " << mesh.cellZones().names() << ")"
                << exit(FatalIOError);
        }
        for (const label c : mesh.cellZones()[zi])
        {
            cellZones_[c].append(z);
        }
    }

    startTime_ = dict.lookupOrDefault<scalar>
    (
        "startTime", this->owner().time().startTime().value()
    );
    samplesPerCell_ = dict.lookupOrDefault<label>("samplesPerCell", 64);
    totalSamples_ = dict.lookupOrDefault<scalar>("totalSamples", 2e6);
    const scalar cmu = dict.lookupOrDefault<scalar>("Cmu", 0.09);
    // each value named with its range (quiet comparisons: NaN refused)
    const auto refuse = [&dict](const char* key, const scalar v, const char* range)
    {
        FatalIOErrorInFunction(dict)
            << "wellMixedCheck: " << key << " " << v << " is outside " << range
            << exit(FatalIOError);
    };
    if (samplesPerCell_ < 1 || samplesPerCell_ > 100000)
    {
        refuse("samplesPerCell", samplesPerCell_, "1 .. 100000");
    }
    if (!(totalSamples_ >= 0 && totalSamples_ <= 1e9))
    {
        refuse("totalSamples", totalSamples_, "0 .. 1e9");
    }
    if (!std::isfinite(startTime_))
    {
        refuse("startTime", startTime_, "the finite numbers");
    }
    // y+ of the bands: u* of the near-wall model's wallCell scale (the C
    // core: max(u_tau, Cmu^(1/4) k_wallcell^(1/2)))
    if
    (
        swd_set(model_, "Cmu", cmu) != SWD_OK
     || swd_set_scale(model_, SWD_USTAR_WALLCELL) != SWD_OK
     || swd_commit(model_) != SWD_OK
    )
    {
        FatalIOErrorInFunction(dict)
            << "wellMixedCheck: " << swd_errmsg(model_) << exit(FatalIOError);
    }
}


template<class CloudType>
Foam::label Foam::WellMixedCheck<CloudType>::band
(
    const label celli,
    const point& x
) const
{
    const label f = nearestFace_[celli];
    if (f < 0)
    {
        return nBands() - 1;
    }
    const fvMesh& mesh = this->owner().mesh();
    const scalar yp =
        snowWallDistance(mesh, f, x)*uStar_[f - mesh.nInternalFaces()]
       /nu_[celli];
    label b = 0;
    while (b + 1 < nBands() && yp >= edges_[b + 1])
    {
        ++b;
    }
    return b;
}


template<class CloudType>
void Foam::WellMixedCheck<CloudType>::refreshFlow()
{
    const fvMesh& mesh = this->owner().mesh();
    const turbulenceModel* turb =
        snowFindTurbulence(mesh, this->owner().U().group());
    if (!turb)
    {
        FatalErrorInFunction
            << "wellMixedCheck: no turbulence model of "
            << this->owner().U().name() << " in the registry: the bands need"
            << " the wall's u*" << exit(FatalError);
    }
    scalarField uTau;
    snowFrictionVelocity(*turb, patches_, uTau);
    const scalarField k(turb->k()().primitiveField());
    nu_ = turb->nu()().primitiveField();
    uStar_ = uTau;
    for (const label pi : patches_)
    {
        const polyPatch& pp = mesh.boundaryMesh()[pi];
        forAll(pp, i)
        {
            const label f = pp.start() + i;
            const label bf = f - mesh.nInternalFaces();
            swd_local at = {};
            at.u_tau = uTau[bf];
            at.nu = 1;
            at.k_wall = max(k[mesh.faceOwner()[f]], scalar(0));
            swd_stats st;
            if (swd_stats_at(model_, &at, &st) != SWD_OK)
            {
                FatalErrorInFunction
                    << "wellMixedCheck: the wall face " << f << " of "
                    << pp.name() << ": u_tau " << at.u_tau << ", k "
                    << at.k_wall << ": not a turbulent wall layer"
                    << exit(FatalError);
            }
            uStar_[bf] = st.ustar;
        }
    }
}


template<class CloudType>
void Foam::WellMixedCheck<CloudType>::buildReference()
{
    const fvMesh& mesh = this->owner().mesh();
    const label nb = nBands();
    volume_.setSize(nSlots());
    volume_ = 0;
    volume2_.setSize(nSlots());
    volume2_ = 0;
    scalar vTotal = gSum(mesh.V());
    boolList atWall(mesh.nCells(), false);
    for (const label pi : patches_)
    {
        for (const label c : mesh.boundaryMesh()[pi].faceCells())
        {
            atWall[c] = true;
        }
    }
    Random rnd(20261207 + Pstream::myProcNo());
    label nSamples = 0;
    forAll(mesh.V(), celli)
    {
        const List<tetIndices> tets =
            polyMeshTetDecomposition::cellTetIndices(mesh, celli);
        scalarList cum(tets.size());
        scalar vc = 0;
        forAll(tets, t)
        {
            vc += max(tets[t].tet(mesh).mag(), scalar(0));
            cum[t] = vc;
        }
        if (!(vc > 0))
        {
            continue;
        }
        label n = max
        (
            samplesPerCell_,
            label(ceil(totalSamples_*mesh.V()[celli]/vTotal))
        );
        if (atWall[celli])
        {
            n *= 8;
        }
        const scalar w = mesh.V()[celli]/n;
        const labelList& zs = cellZones_[celli];
        for (label s = 0; s < n; ++s)
        {
            const scalar r = rnd.sample01<scalar>()*vc;
            label t = 0;
            while (t + 1 < tets.size() && cum[t] < r)
            {
                ++t;
            }
            const point x = tets[t].tet(mesh).randomPoint(rnd);
            const label b = band(celli, x);
            volume_[b] += w;
            volume2_[b] += w*w;
            volume_[nb] += w;
            volume2_[nb] += w*w;
            for (const label z : zs)
            {
                const label o = (z + 1)*(nb + 1);
                volume_[o + b] += w;
                volume2_[o + b] += w*w;
                volume_[o + nb] += w;
                volume2_[o + nb] += w*w;
            }
        }
        nSamples += n;
    }
    Pstream::listCombineGather(volume_, plusEqOp<scalar>());
    Pstream::listCombineScatter(volume_);
    Pstream::listCombineGather(volume2_, plusEqOp<scalar>());
    Pstream::listCombineScatter(volume2_);
    reduce(nSamples, sumOp<label>());
    Info<< "    wellMixedCheck " << this->modelName() << ": the uniform "
        << "reference from " << nSamples << " points in "
        << returnReduce(mesh.nCells(), sumOp<label>()) << " cells; window "
        << "from t = " << startTime_ << endl;
    haveReference_ = true;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::WellMixedCheck<CloudType>::WellMixedCheck
(
    const dictionary& dict,
    CloudType& owner,
    const word& modelName
)
:
    CloudFunctionObject<CloudType>(dict, owner, modelName, typeName),
    model_(swd_alloc()),
    haveReference_(false),
    parcelTime_(0),
    parcelTime2_(0),
    countTime_(0),
    wMin_(GREAT),
    wMax_(-GREAT),
    window_(0)
{
    if (!model_)
    {
        FatalErrorInFunction << "wellMixedCheck: out of memory" << exit(FatalError);
    }
    readSettings(this->coeffDict());
    nearestFace_ = snowNearestWallFace(owner.mesh(), patches_);
    occupancy_.setSize(nSlots(), Zero);
    occupancy2_.setSize(nSlots(), Zero);
    count_.setSize(nSlots(), Zero);
    batch_.setSize(nBatch, scalarList(nSlots() + 1, Zero));
}


template<class CloudType>
Foam::WellMixedCheck<CloudType>::WellMixedCheck
(
    const WellMixedCheck<CloudType>& wm
)
:
    CloudFunctionObject<CloudType>(wm),
    model_(swd_alloc()),
    patches_(wm.patches_),
    edges_(wm.edges_),
    zoneNames_(wm.zoneNames_),
    cellZones_(wm.cellZones_),
    startTime_(wm.startTime_),
    samplesPerCell_(wm.samplesPerCell_),
    totalSamples_(wm.totalSamples_),
    nearestFace_(wm.nearestFace_),
    uStar_(wm.uStar_),
    nu_(wm.nu_),
    haveReference_(wm.haveReference_),
    volume_(wm.volume_),
    volume2_(wm.volume2_),
    occupancy_(wm.occupancy_),
    occupancy2_(wm.occupancy2_),
    count_(wm.count_),
    batch_(wm.batch_),
    parcelTime_(wm.parcelTime_),
    parcelTime2_(wm.parcelTime2_),
    countTime_(wm.countTime_),
    wMin_(wm.wMin_),
    wMax_(wm.wMax_),
    window_(wm.window_)
{
    // a fresh C model with the same settings (the core has no copy)
    readSettings(this->coeffDict());
}


template<class CloudType>
Foam::WellMixedCheck<CloudType>::~WellMixedCheck()
{
    swd_free(model_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::WellMixedCheck<CloudType>::preEvolve()
{
    const Time& time = this->owner().time();
    if (time.value() > startTime_ + 0.5*time.deltaTValue())
    {
        if (!haveReference_)
        {
            // the bands with the flow of the window's start
            refreshFlow();
            buildReference();
        }
        window_ += time.deltaTValue();
    }
}


template<class CloudType>
void Foam::WellMixedCheck<CloudType>::postMove
(
    parcelType& p,
    const scalar dt,
    const point&,
    bool& keepParticle
)
{
    // every sub-step, before anything else: a loop that does not advance
    // ends the parcel's step (the check itself may be far from its window)
    snowTrackingStall(stall_, p, "wellMixedCheck", this->modelName());
    const Time& time = this->owner().time();
    if
    (
        !haveReference_ || !keepParticle || !(dt > 0)
     || !(time.value() > startTime_ + 0.5*time.deltaTValue())
    )
    {
        return;
    }
    const label nb = nBands();
    const label celli = p.cell();
    const label b = band(celli, p.position());
    const scalar span = max(time.endTime().value() - startTime_, VSMALL);
    const label k = min
    (
        nBatch - 1,
        max(label(0), label((time.value() - startTime_)/span*nBatch))
    );
    scalarList& bk = batch_[k];
    const scalar w = p.nParticle();
    wMin_ = min(wMin_, w);
    wMax_ = max(wMax_, w);
    auto add = [&](const label slot)
    {
        occupancy_[slot] += w*dt;
        occupancy2_[slot] += w*w*dt;
        count_[slot] += dt;
        bk[slot] += w*dt;
    };
    add(b);
    add(nb);
    for (const label z : cellZones_[celli])
    {
        const label o = (z + 1)*(nb + 1);
        add(o + b);
        add(o + nb);
    }
    bk[nSlots()] += w*dt;
    parcelTime_ += w*dt;
    parcelTime2_ += w*w*dt;
    countTime_ += dt;
}


template<class CloudType>
void Foam::WellMixedCheck<CloudType>::write()
{
    if (!haveReference_)
    {
        return;
    }
    scalarList occ(occupancy_);
    Pstream::listCombineGather(occ, plusEqOp<scalar>());
    scalarList occ2(occupancy2_);
    Pstream::listCombineGather(occ2, plusEqOp<scalar>());
    scalarList cnt(count_);
    Pstream::listCombineGather(cnt, plusEqOp<scalar>());
    const scalar pt2 = returnReduce(parcelTime2_, sumOp<scalar>());
    const scalar ct = returnReduce(countTime_, sumOp<scalar>());
    const scalar wLo = returnReduce(wMin_, minOp<scalar>());
    const scalar wHi = returnReduce(wMax_, maxOp<scalar>());
    // weighted when the weights differ (beyond rounding)
    const bool weighted = wHi > wLo*(1 + 1e-9);
    List<scalarList> bat(batch_);
    for (scalarList& b : bat)
    {
        Pstream::listCombineGather(b, plusEqOp<scalar>());
    }
    const scalar pt = returnReduce(parcelTime_, sumOp<scalar>());
    // (collective: counted on every processor before the master writes alone)
    const label nStall = snowStallCount(stall_);
    if (!Pstream::master() || !(pt > 0) || !(window_ > 0))
    {
        return;
    }
    const label nb = nBands();
    const scalar vAll = volume_[nb];
    const scalar nMean = ct/window_;      // parcels, counted
    const fileName dir = this->outputDir()/this->owner().time().timeName();
    mkDir(dir);
    OFstream os(dir/"wellMixed.dat");
    os.precision(6);
    os  << "# wellMixedCheck " << this->modelName() << " of cloud "
        << this->owner().name() << ": the parcels' time-averaged share of "
        << "each region and y+ band against its share of the volume" << nl
        << "# window " << startTime_ << " .. "
        << this->owner().time().value() << " s, mean parcels " << nMean
        << (weighted ? " (weighted by nParticle)" : "")
        << ", y+ = y max(u_tau, Cmu^(1/4) k_wallcell^(1/2)) / nu" << nl
        << "# region band yplus_lo yplus_hi volume_share volume_share_se"
        << " parcel_share ratio se_binomial se_batch verdict" << nl;
    scalar worst = 0;
    word worstName("none");
    label nFail = 0;
    for (label r = 0; r <= zoneNames_.size(); ++r)
    {
        const word region(r == 0 ? word("all") : zoneNames_[r - 1]);
        for (label b = 0; b <= nb; ++b)
        {
            const label slot = r*(nb + 1) + b;
            if (r == 0 && b == nb)
            {
                continue;       // the whole domain: 1 by definition
            }
            const scalar p = volume_[slot]/vAll;
            // the Monte Carlo error of the volume share (weighted samples)
            const scalar pse = sqrt(max(volume2_[slot], scalar(0)))/vAll;
            const scalar q = occ[slot]/pt;
            const scalar ratio = p > 0 ? q/p : 0;
            // the binomial error of one snapshot under uniformity: with
            // weights the delta method's (sums of w and w^2 per snapshot)
            scalar seBin = 0;
            if (p > 0 && !weighted)
            {
                seBin = sqrt(max(1 - p, scalar(0))/(nMean*p));
            }
            else if (p > 0)
            {
                const scalar s1 = pt/window_, s2 = pt2/window_;
                const scalar s2b = occ2[slot]/window_;
                seBin = sqrt
                (
                    max(s2b*sqr(1 - p) + max(s2 - s2b, scalar(0))*sqr(p), scalar(0))
                )/(s1*p);
            }
            // batch means of the ratio
            scalar s1 = 0, s2 = 0;
            label nbat = 0;
            for (const scalarList& bk : bat)
            {
                if (bk[nSlots()] > 0 && p > 0)
                {
                    const scalar rk = bk[slot]/bk[nSlots()]/p;
                    s1 += rk;
                    s2 += rk*rk;
                    ++nbat;
                }
            }
            const scalar seBat = nbat > 1
                ? sqrt(max(s2/nbat - sqr(s1/nbat), scalar(0))/(nbat - 1))
                : scalar(0);
            // fewer than 5 parcels expected: the binomial error's normal
            // approximation does not hold, one parcel parked there is a
            // ratio of 1/(N p); the band is listed, not judged
            // (weighted: the parcels expected under uniformity with the
            // region's own mean weight, the heaviest where it holds none)
            const scalar wb =
                cnt[slot] > 0 ? occ[slot]/cnt[slot] : max(wHi, VSMALL);
            const bool few =
                p > 0 && (weighted ? p*(pt/window_)/wb < 5 : nMean*p < 5);
            const bool ok =
                p > 0
             && (few || mag(ratio - 1) <= 0.1 || mag(ratio - 1) <= 2*seBin);
            if (p > 0 && !few && mag(ratio - 1) > worst)
            {
                worst = mag(ratio - 1);
                worstName = region + ":" + (b == nb ? word("whole") : Foam::name(b));
            }
            nFail += (p > 0 && !ok);
            os  << region << ' '
                << (b == nb ? word("whole") : word("y+")) << ' '
                << (b == nb ? scalar(0) : edges_[b]) << ' '
                << (b == nb || b + 1 == nb ? scalar(-1) : edges_[b + 1]) << ' '
                << p << ' ' << pse << ' ' << q << ' ' << ratio << ' ' << seBin
                << ' ' << seBat << ' '
                << (p > 0 ? (few ? "few" : (ok ? "ok" : "FAIL")) : "empty") << nl;
        }
    }
    Info<< "    wellMixedCheck " << this->modelName() << ": mean parcels "
        << nMean << ", largest deviation from uniform " << worst << " ("
        << worstName << "), " << nFail << " region(s) beyond 10 % and two "
        << "standard errors (fewer than 5 parcels expected: not judged)";
    if (nStall > 0)
    {
        Info<< "; " << nStall << " tracking step(s) ended by the stall guard";
    }
    Info<< endl;
}


// ************************************************************************* //
