/*---------------------------------------------------------------------------*\
  SnowWall: wallmodel/OpenFOAM/snowNearWall (see SnowNearWall.H)
\*---------------------------------------------------------------------------*/

#include "SnowNearWall.H"
#include "SnowWallInteraction.H"
#include "snowTrackingStall.H"
#include "turbulenceModel.H"
#include "snowWallLayer.H"
#include "Pstream.H"
#include "OSspecific.H"
#include "StringStream.H"
#include "volPointInterpolation.H"
#include "wallPolyPatch.H"

#include "swp_nearwall.h"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
void Foam::SnowNearWall<CloudType>::readSettings(const dictionary& dict)
{
    // every key of this dictionary is known: a misspelt one is an error
    wordList known
    ({"type", "patches", "closure", "depositionClosure", "velocityScale"});
    for (size_t k = 0; swd_key(k); ++k)
    {
        known.append(word(swd_key(k)));
    }
    for (const entry& e : dict)
    {
        if (!known.found(e.keyword()))
        {
            FatalIOErrorInFunction(dict)
                << "snowNearWall: unknown key '" << e.keyword()
                << "' (known: " << known << ")" << exit(FatalIOError);
        }
    }

    for (size_t k = 0; swd_key(k); ++k)
    {
        const word key(swd_key(k));
        scalar v;
        if (dict.readIfPresent(key, v))
        {
            if (swd_set(model_, key.c_str(), v) != SWD_OK)
            {
                FatalIOErrorInFunction(dict)
                    << "snowNearWall: " << swd_errmsg(model_)
                    << exit(FatalIOError);
            }
        }
    }

    // the wall layer's velocity scale u*: max (default), wallShear, turbulence
    const word scale(dict.lookupOrDefault<word>("velocityScale", "max"));
    if (swd_set_scale(model_, swd_scale_of(scale.c_str())) != SWD_OK)
    {
        FatalIOErrorInFunction(dict)
            << "snowNearWall: velocityScale '" << scale << "' is not max,"
            << " wallCell, wallShear or turbulence" << exit(FatalIOError);
    }

    const bool closure = dict.lookupOrDefault<bool>("closure", true);
    // a depositionClosure given as a value is an error, not "no closure at
    // all"
    const entry* ce = dict.findEntry("depositionClosure", keyType::LITERAL);
    if (ce && !ce->isDict())
    {
        FatalIOErrorInFunction(dict)
            << "snowNearWall: depositionClosure is not a sub-dictionary { ... } "
            << "(#include the file of snowdeposit calibrate, or drop the key)"
            << exit(FatalIOError);
    }
    const dictionary* cd = dict.findDict("depositionClosure");
    if (closure && cd)
    {
        // the CRW the closure was calibrated with must be the one in use
        for (size_t k = 0; swd_key(k); ++k)
        {
            const word key(swd_key(k));
            const scalar cal = cd->get<scalar>(key);
            const scalar use = swd_get(model_, key.c_str());
            if (mag(cal - use) > 1e-9*max(mag(cal), scalar(1)))
            {
                FatalIOErrorInFunction(*cd)
                    << "snowNearWall: the closure was calibrated with " << key
                    << " " << cal << ", the model uses " << use
                    << ": recalibrate (snowdeposit calibrate --set " << key
                    << "=" << use << ") or use the same setting"
                    << exit(FatalIOError);
            }
        }
        const scalarList tau(cd->lookup("tauPlus"));
        const scalarList vs(cd->lookup("vPlusSublayer"));
        if (tau.size() != vs.size())
        {
            FatalIOErrorInFunction(*cd)
                << "snowNearWall: tauPlus has " << tau.size()
                << " values, vPlusSublayer " << vs.size()
                << exit(FatalIOError);
        }
        const scalar ysub = cd->get<scalar>("sublayerYPlus");
        if
        (
            swd_set_closure(model_, ysub, tau.cdata(), vs.cdata(), tau.size())
         != SWD_OK
        )
        {
            FatalIOErrorInFunction(*cd)
                << "snowNearWall: " << swd_errmsg(model_) << exit(FatalIOError);
        }
    }
    else if (closure && dict.found("closure"))
    {
        FatalIOErrorInFunction(dict)
            << "snowNearWall: closure on needs the coefficients"
            << " depositionClosure { ... } (#include \"deposition.coeffs\","
            << " written by snowdeposit calibrate)" << exit(FatalIOError);
    }
    if (swd_commit(model_) != SWD_OK)
    {
        FatalIOErrorInFunction(dict)
            << "snowNearWall: " << swd_errmsg(model_) << exit(FatalIOError);
    }

    // the walls
    const polyBoundaryMesh& bm = this->owner().mesh().boundaryMesh();
    patches_ = snowWallPatches(bm, dict, "snowNearWall");

    // this object is the dispersion: the cloud's own must be off (the cloud
    // functions are built before the dispersion model: read its keyword)
    const word disp
    (
        this->owner().subModelProperties().template
            lookupOrDefault<word>("dispersionModel", "none")
    );
    if (disp != "none")
    {
        FatalIOErrorInFunction(dict)
            << "snowNearWall replaces the dispersion model: set"
            << " dispersionModel none; in the subModels of "
            << this->owner().name() << "Properties (it is " << disp << ")"
            << exit(FatalIOError);
    }

    char buf[512];
    swd_describe(model_, buf, sizeof buf);
    Info<< "    snowNearWall " << this->modelName() << ": " << buf << nl
        << "        walls " << UIndirectList<word>(bm.names(), patches_)
        << ", sublayer closure ";
    if (swd_closure_on(model_))
    {
        Info<< "on (law " << cd->lookupOrDefault<word>("law", "?")
            << ", sublayer y+ < " << cd->get<scalar>("sublayerYPlus") << ")";
    }
    else
    {
        Info<< "off";
    }
    Info<< endl;
}


template<class CloudType>
void Foam::SnowNearWall<CloudType>::buildNearest()
{
    nearestFace_ = snowNearestWallFace(this->owner().mesh(), patches_);
}


template<class CloudType>
void Foam::SnowNearWall<CloudType>::checkTurbulent
(
    const turbulenceModel& turb
) const
{
    // a laminar flow has k = epsilon = 0: the walk would add nothing, and the
    // closure deposit by a u_tau without turbulence: refused, so that the
    // model never runs as dispersion none without a word
    const word sim(turb.lookupOrDefault<word>("simulationType", word::null));
    if (sim == "laminar")
    {
        FatalIOErrorInFunction(this->coeffDict())
            << "snowNearWall: the flow is laminar (simulationType laminar in "
            << turb.objectPath() << "): the near-wall model walks the "
            << "particles with the turbulence model's k and epsilon. Use a "
            << "RAS or LES turbulence model, or remove this cloud function"
            << exit(FatalIOError);
    }
}


template<class CloudType>
void Foam::SnowNearWall<CloudType>::refreshFlow()
{
    const CloudType& cloud = this->owner();
    const fvMesh& mesh = cloud.mesh();
    const turbulenceModel* turb = snowFindTurbulence(mesh, cloud.U().group());
    if (!turb)
    {
        FatalErrorInFunction
            << "snowNearWall: no turbulence model of "
            << cloud.U().name() << " in the registry: the model needs its k,"
            << " epsilon and wall shear stress" << exit(FatalError);
    }
    checkTurbulent(*turb);
    {
        const tmp<volScalarField> tk(turb->k());
        k_ = tk().primitiveField();
        kPoints_ = volPointInterpolation::New(mesh).interpolate(tk())().primitiveField();
    }
    epsilon_ = turb->epsilon()().primitiveField();
    nu_ = turb->nu()().primitiveField();

    // friction velocity of every face of the patches
    snowFrictionVelocity(*turb, patches_, uTau_);
}


template<class CloudType>
Foam::label Foam::SnowNearWall<CloudType>::patchSlot(const label f) const
{
    const polyBoundaryMesh& bm = this->owner().mesh().boundaryMesh();
    const label pi = bm.whichPatch(f);
    forAll(patches_, s)
    {
        if (patches_[s] == pi) return s;
    }
    return -1;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::SnowNearWall<CloudType>::SnowNearWall
(
    const dictionary& dict,
    CloudType& owner,
    const word& modelName
)
:
    CloudFunctionObject<CloudType>(dict, owner, modelName, typeName),
    model_(swd_alloc()),
    patches_(),
    nearestFace_(),
    uTau_(),
    k_(),
    kPoints_(),
    epsilon_(),
    nu_(),
    nClosure_(),
    mClosure_(),
    nClosure0_(),
    mClosure0_(),
    eClosure_(),
    eClosure0_(),
    seriesPtr_(),
    records_()
{
    if (!model_)
    {
        FatalErrorInFunction << "snowNearWall: out of memory" << exit(FatalError);
    }
    readSettings(this->coeffDict());
    {
        // checked at set-up when the flow's turbulence model is already
        // there (most solvers make it before the cloud), else at the first
        // step
        const turbulenceModel* turb =
            snowFindTurbulence(owner.mesh(), owner.U().group());
        if (turb)
        {
            checkTurbulent(*turb);
        }
    }
    buildNearest();
    nClosure_.setSize(patches_.size(), Zero);
    mClosure_.setSize(patches_.size(), Zero);
    nClosure0_.setSize(patches_.size(), Zero);
    mClosure0_.setSize(patches_.size(), Zero);
    eClosure_.setSize(patches_.size(), Zero);
    eClosure0_.setSize(patches_.size(), Zero);
    records_.setSize(patches_.size());
    this->getModelProperty("nClosure", nClosure0_);
    this->getModelProperty("massClosure", mClosure0_);
    this->getModelProperty("expectedClosure", eClosure0_);
    if
    (
        nClosure0_.size() != patches_.size()
     || mClosure0_.size() != patches_.size()
     || eClosure0_.size() != patches_.size()
    )
    {
        // another set of walls than the run restarted from: start at 0
        nClosure0_ = labelList(patches_.size(), label(0));
        mClosure0_ = scalarList(patches_.size(), scalar(0));
        eClosure0_ = scalarList(patches_.size(), scalar(0));
    }
}


template<class CloudType>
Foam::SnowNearWall<CloudType>::SnowNearWall(const SnowNearWall<CloudType>& nw)
:
    CloudFunctionObject<CloudType>(nw),
    model_(nullptr),
    patches_(nw.patches_),
    nearestFace_(nw.nearestFace_),
    uTau_(nw.uTau_),
    k_(nw.k_),
    kPoints_(nw.kPoints_),
    epsilon_(nw.epsilon_),
    nu_(nw.nu_),
    nClosure_(nw.nClosure_),
    mClosure_(nw.mClosure_),
    nClosure0_(nw.nClosure0_),
    mClosure0_(nw.mClosure0_),
    eClosure_(nw.eClosure_),
    eClosure0_(nw.eClosure0_),
    seriesPtr_(),
    records_(nw.records_)
{
    // a fresh C model with the same settings (the core has no copy)
    model_ = swd_alloc();
    readSettings(this->coeffDict());
}


template<class CloudType>
Foam::SnowNearWall<CloudType>::~SnowNearWall()
{
    swd_free(model_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::SnowNearWall<CloudType>::preEvolve()
{
    refreshFlow();
}


template<class CloudType>
void Foam::SnowNearWall<CloudType>::wallLayerAt
(
    const parcelType& p,
    const label f,
    swd_local& at,
    vector& gradK,
    vector& es,
    vector& en,
    vector& ez
) const
{
    const CloudType& cloud = this->owner();
    const fvMesh& mesh = cloud.mesh();
    const label celli = p.cell();

    at.nu = nu_[celli];
    at.eps = max(epsilon_[celli], scalar(0));
    snowCellPointValueGrad
    (
        mesh, k_, kPoints_, p.currentTetIndices(), p.coordinates(), at.k, gradK
    );
    at.k = max(at.k, scalar(0));
    const vector Uc = cloud.U()[celli];
    vector n(0, -1, 0);         // the wall's outward normal (any without a wall)
    const point& x = p.position();
    if (f >= 0)
    {
        n = mesh.faceAreas()[f]/mag(mesh.faceAreas()[f]);
        // the distance to the face itself (its nearest point), not to its
        // plane: away from the face's edges the two are the same, beyond them
        // the plane would bring a far parcel into the wall layer
        at.y = snowWallDistance(mesh, f, x);
        at.u_tau = uTau_[f - mesh.nInternalFaces()];
        at.k_wall = max(k_[mesh.faceOwner()[f]], scalar(0));
    }
    else
    {
        at.y = -1;
        at.u_tau = 0;
    }
    // the wall frame: wall-normal (into the fluid), streamwise, spanwise
    const double nOut[3] = {n.x(), n.y(), n.z()}, uc[3] = {Uc.x(), Uc.y(), Uc.z()};
    double fs[3], fn[3], fz[3];
    swd_wall_frame(nOut, uc, fs, fn, fz);
    es = vector(fs[0], fs[1], fs[2]);
    en = vector(fn[0], fn[1], fn[2]);
    ez = vector(fz[0], fz[1], fz[2]);
    at.grad_k[0] = gradK & es;
    at.grad_k[1] = gradK & en;
    at.grad_k[2] = gradK & ez;
}


template<class CloudType>
void Foam::SnowNearWall<CloudType>::reflectAtWall
(
    const parcelType& p,
    vector& K,
    vector& W
) const
{
    const fvMesh& mesh = this->owner().mesh();

    // on a wall face the patch interaction comes next: the fluid velocity
    // the parcel sees is reflected with it (Wilson & Flesch's perfect
    // reflection). The kick points into the wall, which a rebound reverses,
    // and the kept fluctuation away from it
    if (p.onBoundaryFace())
    {
        const label hf = p.face();
        const polyPatch& hp = mesh.boundaryMesh()[mesh.boundaryMesh().whichPatch(hf)];
        if (isA<wallPolyPatch>(hp))
        {
            const vector nh = mesh.faceAreas()[hf]/mag(mesh.faceAreas()[hf]);
            const scalar kn = K & nh, wn = W & nh;
            if (kn < 0) K -= 2*kn*nh;
            if (wn > 0) W -= 2*wn*nh;
        }
    }
}


template<class CloudType>
void Foam::SnowNearWall<CloudType>::depositByClosure
(
    parcelType& p,
    bool& keepParticle,
    const scalar dt,
    const label f,
    const swd_local& at,
    const swd_stats& st,
    const scalar muc,
    const vector& es,
    const vector& en
)
{
    CloudType& cloud = this->owner();
    const fvMesh& mesh = cloud.mesh();
    Random& rnd = cloud.rndGen();
    const point& x = p.position();

    const scalar tauStokes = swp_tau_p(p.rho(), p.d(), muc, 0);
    const scalar lambda = swd_deposit_rate(model_, &st, at.nu, tauStokes);
    if (!(lambda > 0))
    {
        return;
    }
    const scalar prob = -std::expm1(-lambda*dt);
    const label s = patchSlot(f);
    eClosure_[s] += prob;
    if (rnd.sample01<scalar>() >= prob)
    {
        return;
    }

    const polyPatch& pp = mesh.boundaryMesh()[patches_[s]];
    const scalar mp = p.mass()*p.nParticle();
    typedef SnowWallInteraction<CloudType> snowType;
    snowType* snow = dynamic_cast<snowType*>(&cloud.patchInteraction());
    if (snow)
    {
        // the impact: the parcel's own wall-normal velocity towards the wall,
        // and along the wall the fluid's speed at contact height (the
        // viscous sublayer carries it: u+ = y+ at y = d/2)
        const scalar uContact = swd_contact_speed(&st, at.nu, p.d());
        const scalar Un = -(p.U() & en);
        const vector Uimp =
            -max(Un, scalar(0))*en + es*uContact;
        const vector Usave = p.U();
        p.U() = Uimp;
        bool keep = true;
        if (!snow->impactSnow(p, pp, f - pp.start(), keep))
        {
            p.U() = Usave;      // not a snow wall: the closure leaves it
            return;
        }
        keepParticle = keep;
        if (p.active())
        {
            // bounced or ripped off: on its way with the rebound velocity
            // plus the wall's velocity along it
            p.U() += (Usave - (Usave & en)*en) - es*uContact;
        }
    }
    else
    {
        // any other patch interaction model: every wall contact a deposit
        cloud.patchInteraction().addToEscapedParcels(mp);
        keepParticle = false;
    }
    ++nClosure_[s];
    mClosure_[s] += mp;
    OStringStream rec;
    rec.precision(10);
    rec << this->owner().time().value() << ' ' << x.x() << ' ' << x.y() << ' '
        << x.z() << ' ' << p.origProc() << ' ' << p.origId() << ' '
        << p.nParticle() << ' ' << p.d() << ' ' << p.rho();
    records_[s].append(rec.str());
}


template<class CloudType>
void Foam::SnowNearWall<CloudType>::postMove
(
    parcelType& p,
    const scalar dt,
    const point&,              // the start of the step: the walk takes the end
    bool& keepParticle
)
{
    // every sub-step, before anything else: a loop that does not advance
    // ends the parcel's step
    snowTrackingStall(stall_, p, "snowNearWall", this->modelName());
    if (!keepParticle || !p.active() || !(dt > ROOTVSMALL))
    {
        return;
    }
    CloudType& cloud = this->owner();
    const label celli = p.cell();
    const label f = nearestFace_[celli];

    // the place now, where the coming step starts (the end of this tracking
    // step): wall distance, wall frame, and k with its gradient from the
    // cell-point interpolant of k in the parcel's tet
    swd_local at = {};
    vector gradK(Zero), es, en, ez;
    wallLayerAt(p, f, at, gradK, es, en, ez);
    const vector Uc = cloud.U()[celli];
    const point& x = p.position();

    Random& rnd = cloud.rndGen();
    // the parcel's normalized fluctuation (tTurb 1: drawn by this object)
    double w[3];
    if (p.tTurb() != 1)
    {
        for (int i = 0; i < 3; ++i) w[i] = rnd.GaussNormal<scalar>();
        p.tTurb() = 1;
    }
    else
    {
        const vector& wg = p.UTurb();
        w[0] = wg & es;
        w[1] = wg & en;
        w[2] = wg & ez;
    }

    // relaxation time with the parcel's slip (Schiller-Naumann)
    const scalar rhoc = cloud.rho()[celli];
    const scalar muc = cloud.mu()[celli];
    const scalar Re = rhoc*mag(Uc - p.U())*p.d()/muc;
    const scalar tauP = swp_tau_p(p.rho(), p.d(), muc, Re);

    const double xi[3] =
    {
        rnd.GaussNormal<scalar>(),
        rnd.GaussNormal<scalar>(),
        rnd.GaussNormal<scalar>()
    };
    double kick[3];
    swd_stats st;
    const int rc = swd_advance(model_, &at, dt, tauP, w, xi, kick, &st);
    if (rc != SWD_OK)
    {
        FatalErrorInFunction
            << "snowNearWall: invalid state of parcel " << p.origId()
            << " at " << x << ": y " << at.y << " u_tau "
            << at.u_tau << " nu " << at.nu << " k " << at.k << " grad k "
            << gradK << " epsilon " << at.eps << " dt " << dt << " tau_p "
            << tauP << exit(FatalError);
    }
    vector K(kick[0]*es + kick[1]*en + kick[2]*ez);
    vector W(w[0]*es + w[1]*en + w[2]*ez);
    reflectAtWall(p, K, W);
    p.U() += K;
    p.UTurb() = W;

    // the sublayer closure: reaches the wall at the rate lambda
    if (f < 0 || !swd_closure_on(model_))
    {
        return;
    }
    depositByClosure(p, keepParticle, dt, f, at, st, muc, es, en);
}


template<class CloudType>
void Foam::SnowNearWall<CloudType>::write()
{
    labelList n(nClosure_);
    scalarList m(mClosure_);
    scalarList e(eClosure_);
    Pstream::listCombineGather(n, plusEqOp<label>());
    Pstream::listCombineScatter(n);
    Pstream::listCombineGather(m, plusEqOp<scalar>());
    Pstream::listCombineScatter(m);
    Pstream::listCombineGather(e, plusEqOp<scalar>());
    Pstream::listCombineScatter(e);
    forAll(n, s)
    {
        n[s] += nClosure0_[s];
        m[s] += mClosure0_[s];
        e[s] += eClosure0_[s];
    }
    this->setModelProperty("nClosure", n);
    this->setModelProperty("massClosure", m);
    this->setModelProperty("expectedClosure", e);

    // the records since the last write, gathered on the master
    {
        const Time& time = this->owner().time();
        const polyBoundaryMesh& bm0 = this->owner().mesh().boundaryMesh();
        forAll(patches_, s)
        {
            List<List<string>> all(Pstream::nProcs());
            all[Pstream::myProcNo()] = records_[s];
            Pstream::gatherList(all);
            records_[s].clear();
            if (!Pstream::master()) continue;
            const fileName dir = this->outputDir()/time.timeName();
            mkDir(dir);
            OFstream os(dir/(bm0[patches_[s]].name() + ".post"));
            os  << "# Time (position0 position1 position2) origProc origId"
                << " nParticle d rho" << nl;
            for (const List<string>& l : all)
            {
                for (const string& line : l)
                {
                    os  << line.c_str() << nl;
                }
            }
        }
    }

    const polyBoundaryMesh& bm = this->owner().mesh().boundaryMesh();
    Info<< "    snowNearWall " << this->modelName()
        << ": reached the wall through the sublayer closure:";
    forAll(patches_, s)
    {
        Info<< " " << bm[patches_[s]].name() << " " << n[s] << " (" << m[s]
            << " kg; expected " << e[s] << ")";
    }
    const label nStall = snowStallCount(stall_);
    if (nStall > 0)
    {
        Info<< "; " << nStall << " tracking step(s) ended by the stall guard";
    }
    Info<< endl;

    if (Pstream::master())
    {
        if (!seriesPtr_.valid())
        {
            const Time& time = this->owner().time();
            const fileName dir =
                this->outputDir()/time.timeName(time.startTime().value());
            mkDir(dir);
            seriesPtr_.reset(new OFstream(dir/"snowNearWall.dat"));
            OFstream& os = seriesPtr_();
            os  << "# snowNearWall " << this->modelName()
                << ": parcels (and mass, kg) that reached each wall through"
                << " the sublayer closure, cumulative, and the expected"
                << " number" << nl << "# time";
            forAll(patches_, s)
            {
                os  << tab << bm[patches_[s]].name() << ":n" << tab
                    << bm[patches_[s]].name() << ":mass" << tab
                    << bm[patches_[s]].name() << ":expected";
            }
            os  << nl;
        }
        OFstream& os = seriesPtr_();
        os  << this->owner().time().timeName();
        forAll(patches_, s)
        {
            os  << tab << n[s] << tab << m[s] << tab << e[s];
        }
        os  << endl;
    }
}


// ************************************************************************* //
