/*---------------------------------------------------------------------------*\
  SnowWall: wallmodel/OpenFOAM/parcelSplitting (see ParcelSplitting.H)
\*---------------------------------------------------------------------------*/

#include "ParcelSplitting.H"
#include "treeBoundBox.H"
#include "Pstream.H"
#include "vector2D.H"
#include "KinematicParcel.H"
#include "particle.H"
#include "snowMachineLimits.H"

// * * * * * * * * * * * * * * * Static Data  * * * * * * * * * * * * * * * * //

template<class CloudType>
const Foam::label Foam::ParcelSplitting<CloudType>::maxParcelsDefault;

template<class CloudType>
const Foam::label Foam::ParcelSplitting<CloudType>::maxCopiesDefault;

template<class CloudType>
const Foam::label Foam::ParcelSplitting<CloudType>::maxCopiesLimit;

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
const char* Foam::ParcelSplitting<CloudType>::regionsForm()
{
    return "regions ( name { box (min) (max); factor F; } ... );";
}


template<class CloudType>
Foam::OSstream& Foam::ParcelSplitting<CloudType>::regionError
(
    const fileName& scope,
    const dictionary& rd
)
{
    return FatalIOError
    (
        FUNCTION_NAME, __FILE__, __LINE__,
        scope + "." + rd.dictName(), rd.startLineNumber(), rd.endLineNumber()
    );
}


template<class CloudType>
void Foam::ParcelSplitting<CloudType>::checkKeys() const
{
    const dictionary& dict = this->coeffDict();
    const word& name = this->modelName();

    // every key is known: a misspelt one ('maxCopy') would otherwise be
    // ignored without a word
    const wordList known({"type", "regions", "maxParcels", "maxCopies"});
    for (const entry& e : dict)
    {
        if (!known.found(e.keyword()))
        {
            FatalIOErrorInFunction(dict)
                << "parcelSplitting " << name << ": unknown key '" << e.keyword()
                << "'; the accepted keys are " << known
                << exit(FatalIOError);
        }
    }
}


template<class CloudType>
const Foam::entry& Foam::ParcelSplitting<CloudType>::regionsEntry() const
{
    const dictionary& dict = this->coeffDict();
    const word& name = this->modelName();
    const char* const form = regionsForm();

    // the form is checked before the entries are read: OpenFOAM's own reading
    // of a dictionary as a list aborts with a message naming neither
    const entry* re = dict.findEntry("regions", keyType::LITERAL);
    if (!re)
    {
        FatalIOErrorInFunction(dict)
            << "parcelSplitting " << name << ": missing 'regions': give a list  "
            << form << exit(FatalIOError);
    }
    if (re->isDict())
    {
        FatalIOErrorInFunction(re->dict())
            << "parcelSplitting " << name << ": 'regions' is a dictionary { ... } "
            << "but must be a list in parentheses:  " << form
            << exit(FatalIOError);
    }
    return *re;
}


template<class CloudType>
void Foam::ParcelSplitting<CloudType>::checkRegionList(ITstream& is) const
{
    const word& name = this->modelName();
    const char* const form = regionsForm();

    if
    (
        is.empty()
     || !is[0].isPunctuation()
     || is[0].pToken() != token::BEGIN_LIST
    )
    {
        FatalIOErrorInFunction(is)
            << "parcelSplitting " << name << ": 'regions' must be a list in "
            << "parentheses:  " << form << "  got  " << is.toString()
            << exit(FatalIOError);
    }
    // every item: a name, then a { ... } block ('regions ( lower 4 )' read as
    // entries ran into "attempt to read beyond EOF", naming nothing)
    for (label k = 1; k < is.size();)
    {
        const token& t = is[k];
        if (t.isPunctuation() && t.pToken() == token::END_LIST)
        {
            break;
        }
        if (!t.isWord() && !t.isString())
        {
            FatalIOErrorInFunction(is)
                << "parcelSplitting " << name << ": 'regions': expected a "
                << "region name, got " << t << " (item " << k << " of the "
                << "list):  " << form << exit(FatalIOError);
        }
        const string rn(t.isWord() ? string(t.wordToken()) : t.stringToken());
        ++k;
        if
        (
            k >= is.size()
         || !is[k].isPunctuation()
         || is[k].pToken() != token::BEGIN_BLOCK
        )
        {
            FatalIOErrorInFunction(is)
                << "parcelSplitting " << name << ": 'regions': region '"
                << rn.c_str() << "' must be followed by its dictionary "
                << "{ box (min) (max); factor F; }, got "
                << (k < is.size() ? is[k].info() : token().info())
                << ":  " << form << exit(FatalIOError);
        }
        label depth = 0;
        do
        {
            if (is[k].isPunctuation() && is[k].pToken() == token::BEGIN_BLOCK)
            {
                ++depth;
            }
            else if (is[k].isPunctuation() && is[k].pToken() == token::END_BLOCK)
            {
                --depth;
            }
            ++k;
        } while (k < is.size() && depth > 0);
        if (depth > 0)
        {
            FatalIOErrorInFunction(is)
                << "parcelSplitting " << name << ": 'regions': region '"
                << rn.c_str() << "': '{' without its '}':  " << form
                << exit(FatalIOError);
        }
    }
}


template<class CloudType>
void Foam::ParcelSplitting<CloudType>::checkRegion
(
    const label r,
    const dictionary& rd,
    const fileName& scope
) const
{
    const word& name = this->modelName();

    // a region's keys are known: a misspelt 'factr' would otherwise be
    // ignored, and 'box' beside 'boxes' drop the boxes
    const wordList regionKeys({"box", "boxes", "factor"});
    for (const entry& e : rd)
    {
        if (!regionKeys.found(e.keyword()))
        {
            regionError(scope, rd)
                << "parcelSplitting " << name << ": region "
                << regionNames_[r] << ": unknown key '" << e.keyword()
                << "'; the accepted keys are " << regionKeys
                << exit(FatalIOError);
        }
    }
    if (rd.found("box") && rd.found("boxes"))
    {
        regionError(scope, rd)
            << "parcelSplitting " << name << ": region " << regionNames_[r]
            << ": give 'box' or 'boxes', not both" << exit(FatalIOError);
    }
    for (label q = 0; q < r; ++q)
    {
        if (regionNames_[q] == regionNames_[r])
        {
            regionError(scope, rd)
                << "parcelSplitting " << name << ": region '"
                << regionNames_[r] << "' is given twice in 'regions': "
                << "each region needs its own name (both entries would act)"
                << exit(FatalIOError);
        }
    }
}


template<class CloudType>
Foam::treeBoundBoxList Foam::ParcelSplitting<CloudType>::regionBoxes
(
    const label r,
    const dictionary& rd,
    const fileName& scope
) const
{
    const word& name = this->modelName();

    // as boxToCell: "box (min) (max);" or "boxes ((min) (max) ...);",
    // read as plain corner points so that a box given max-first is
    // reported instead of silently reordered
    List<point> corners;
    if (rd.found("box"))
    {
        ITstream& is = rd.lookup("box");
        point lo, hi;
        is >> lo >> hi;
        corners = List<point>({lo, hi});
    }
    else if (rd.found("boxes"))
    {
        corners = List<point>(rd.lookup("boxes"));
    }
    if (corners.size() % 2)
    {
        regionError(scope, rd)
            << "parcelSplitting " << name << ": region " << regionNames_[r]
            << ": 'boxes' holds " << corners.size()
            << " points, not (min) (max) pairs" << exit(FatalIOError);
    }
    treeBoundBoxList bbs(corners.size()/2);
    forAll(bbs, b)
    {
        const point& lo = corners[2*b];
        const point& hi = corners[2*b + 1];
        if (!(lo.x() < hi.x() && lo.y() < hi.y() && lo.z() < hi.z()))
        {
            regionError(scope, rd)
                << "parcelSplitting " << name << ": region " << regionNames_[r]
                << ": box " << lo << " " << hi
                << " needs min < max in x, y, z" << exit(FatalIOError);
        }
        bbs[b] = treeBoundBox(lo, hi);
    }
    if (bbs.empty())
    {
        regionError(scope, rd)
            << "parcelSplitting " << name << ": region " << regionNames_[r]
            << ": needs 'box (min) (max);' or a non-empty"
            << " 'boxes ((min) (max) ...);'" << exit(FatalIOError);
    }
    return bbs;
}


template<class CloudType>
Foam::label Foam::ParcelSplitting<CloudType>::markRegionCells
(
    const label r,
    const treeBoundBoxList& bbs
)
{
    const pointField& cc = this->owner().mesh().cellCentres();

    bitSet& cells = regionCells_[r];
    cells.resize(cc.size());
    label nCells = 0;
    forAll(cc, celli)
    {
        for (const treeBoundBox& bb : bbs)
        {
            if (bb.contains(cc[celli]))
            {
                cells.set(celli);
                ++nCells;
                break;
            }
        }
    }
    return nCells;
}


template<class CloudType>
void Foam::ParcelSplitting<CloudType>::readRegions()
{
    const word& name = this->modelName();
    const char* const form = regionsForm();

    checkKeys();
    const entry& re = regionsEntry();
    ITstream& is = re.stream();
    checkRegionList(is);
    const PtrList<entry> entries(is);

    // a region's entries read from the list carry only their own name: an
    // error names the file and scope of 'regions' and the region's lines
    const fileName scope(re.name());
    if (entries.empty())
    {
        FatalIOErrorInFunction(is)
            << "parcelSplitting " << name << ": 'regions' is empty: give at "
            << "least one region:  " << form << exit(FatalIOError);
    }

    regionNames_.setSize(entries.size());
    regionCells_.setSize(entries.size());
    factor_.setSize(entries.size());

    forAll(entries, r)
    {
        if (!entries[r].isDict())
        {
            FatalIOErrorInFunction(is)
                << "parcelSplitting " << name << ": region entry '"
                << entries[r].keyword() << "' is not a dictionary "
                << "{ box (min) (max); factor F; }:  " << form
                << exit(FatalIOError);
        }
        const dictionary& rd = entries[r].dict();
        regionNames_[r] = entries[r].keyword();
        checkRegion(r, rd, scope);

        // a parcel of the reference mass becomes F parcels: F is bounded by
        // maxCopies, the most parcels one split may make
        const scalar F = rd.get<scalar>("factor");
        if (!std::isfinite(F) || F < 1 || F > maxCopies_)
        {
            regionError(scope, rd)
                << "parcelSplitting " << name << ": region " << regionNames_[r]
                << ": factor " << F << " must be in [1, maxCopies "
                << maxCopies_ << "]: one parcel of the injected mean mass "
                << "becomes F parcels in it; raise maxCopies (at most "
                << maxCopiesLimit << ") to allow more"
                << exit(FatalIOError);
        }
        factor_[r] = F;

        const treeBoundBoxList bbs(regionBoxes(r, rd, scope));
        const label nCells = markRegionCells(r, bbs);
        Info<< "    parcelSplitting: region " << regionNames_[r]
            << ": factor " << F << ", "
            << returnReduce(nCells, sumOp<label>()) << " cells" << endl;
    }
}


template<class CloudType>
Foam::scalar Foam::ParcelSplitting<CloudType>::referenceMass() const
{
    // the injectors' totals are global (reduced by the injection models)
    scalar mass = 0;
    label parcels = 0;
    forAll(this->owner().injectors(), i)
    {
        mass += this->owner().injectors()[i].massInjected();
        parcels += this->owner().injectors()[i].parcelsAddedTotal();
    }
    return parcels > 0 ? mass/parcels : 0;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
void Foam::ParcelSplitting<CloudType>::checkMemory() const
{
    // the parcels the cloud may hold: maxParcels, or fewer when the injected
    // parcels and the largest factor bound them (a copy keeps at least
    // 0.75 m_ref/F: at most N (1 + 4 F/3) parcels are ever made)
    scalar F = 1;
    forAll(factor_, r) F = max(F, factor_[r]);
    const scalar nInj = snowMachine::injectedParcels
    (
        this->owner().subModelProperties().subOrEmptyDict("injectionModels")
    );
    scalar nMax = maxParcels_;
    if (nInj >= 0) nMax = min(nMax, snowMachine::parcelsBound(nInj, F));
    // resident memory per parcel: 0.56 kB measured for the kinematic parcel
    // (the box case, 643 782 parcels: +357 MB), scaled by this parcel
    // type's size
    typedef typename CloudType::parcelType parcelType;
    const scalar perParcel = 560.0*max
    (
        1.0,
        scalar(sizeof(parcelType))/scalar(sizeof(KinematicParcel<particle>))
    );
    const scalar mem = nMax*perParcel;
    const scalar avail = snowMachine::memAvailable();
    const scalar GB = 1e9;
    Info<< "    parcelSplitting: at most " << label(nMax) << " parcels ("
        << (nInj >= 0 && nMax < maxParcels_ ? "injected x (1 + 4F/3), F " : "maxParcels");
    if (nInj >= 0 && nMax < maxParcels_) Info<< F;
    Info<< "; an upper bound) x " << perParcel/1e3 << " kB = " << mem/GB
        << " GB of memory for the cloud, ";
    if (avail >= 0) Info<< avail/GB << " GB available" << endl;
    else Info<< "available memory unknown (/proc/meminfo)" << endl;
    if (avail >= 0 && mem > 0.8*avail)
    {
        FatalIOErrorInFunction(this->coeffDict())
            << "parcelSplitting " << this->modelName() << ": the cloud may "
            << "hold up to " << label(nMax) << " parcels ("
            << (nInj >= 0
                ? std::string("the ") + Foam::name(std::floor(nInj))
                  + " injected split up to factor " + Foam::name(F)
                  + ", and maxParcels " + Foam::name(maxParcels_)
                : std::string("maxParcels ") + Foam::name(maxParcels_)
                  + "; the injected parcels cannot be told from the "
                    "injection models").c_str()
            << ") x " << perParcel/1e3 << " kB = " << mem/GB << " GB, more "
            << "than 80 % of the " << avail/GB << " GB available (MemAvailable "
            << "of /proc/meminfo): lower maxParcels or the factors"
            << exit(FatalIOError);
    }
}


template<class CloudType>
Foam::ParcelSplitting<CloudType>::ParcelSplitting
(
    const dictionary& dict,
    CloudType& owner,
    const word& modelName
)
:
    CloudFunctionObject<CloudType>(dict, owner, modelName, typeName),
    regionNames_(),
    regionCells_(),
    factor_(),
    maxParcels_
    (
        this->coeffDict().template lookupOrDefault<label>
        (
            "maxParcels", maxParcelsDefault
        )
    ),
    maxCopies_
    (
        this->coeffDict().template lookupOrDefault<label>
        (
            "maxCopies", maxCopiesDefault
        )
    ),
    nSplit_(0),
    nCopies_(0),
    capped_(false),
    heavyNoticed_(false)
{
    // the caps first: the factors are checked against maxCopies
    if (maxParcels_ < 1)
    {
        FatalIOErrorInFunction(this->coeffDict())
            << "parcelSplitting " << modelName << ": maxParcels "
            << maxParcels_ << " must be in [1, " << labelMax << "] (the most "
            << "parcels the cloud may hold after splitting; default "
            << maxParcelsDefault << ")" << exit(FatalIOError);
    }
    if (maxCopies_ < 2 || maxCopies_ > maxCopiesLimit)
    {
        FatalIOErrorInFunction(this->coeffDict())
            << "parcelSplitting " << modelName << ": maxCopies " << maxCopies_
            << " must be in [2, " << maxCopiesLimit << "] (the most parcels "
            << "one parcel is split into; default " << maxCopiesDefault << ")"
            << exit(FatalIOError);
    }
    readRegions();
    Info<< "    parcelSplitting: at most " << maxCopies_
        << " parcels from one parcel (maxCopies), at most " << maxParcels_
        << " parcels in the cloud (maxParcels)" << endl;
    checkMemory();
    this->getModelProperty("nSplit", nSplit_);
    this->getModelProperty("nCopies", nCopies_);
}


template<class CloudType>
Foam::ParcelSplitting<CloudType>::ParcelSplitting
(
    const ParcelSplitting<CloudType>& ps
)
:
    CloudFunctionObject<CloudType>(ps),
    regionNames_(ps.regionNames_),
    regionCells_(ps.regionCells_),
    factor_(ps.factor_),
    maxParcels_(ps.maxParcels_),
    maxCopies_(ps.maxCopies_),
    nSplit_(ps.nSplit_),
    nCopies_(ps.nCopies_),
    capped_(ps.capped_),
    heavyNoticed_(ps.heavyNoticed_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::ParcelSplitting<CloudType>::postEvolve()
{
    // m_ref is global (the injection models reduce their totals), so every
    // processor takes the same branch and meets the same reduction
    const scalar mRef = referenceMass();
    if (mRef <= 0)
    {
        CloudFunctionObject<CloudType>::postEvolve();
        return;
    }
    CloudType& cloud = this->owner();

    // 1. the parcels to split and their n = round(m F / m_ref), before any
    //    copy is added. n never exceeds maxCopies: a parcel that would need
    //    more (heavier than maxCopies/F reference masses) is left whole, so
    //    every copy made has the target mass m_ref/F to rounding (m F/m_ref
    //    <= 1.25 < 1.5) and is not split again at that factor (the copies of
    //    a capped split would be heavier than the target and be split again
    //    step after step)
    DynamicList<parcelType*> parcels;
    DynamicList<label> nCopies;
    scalar wanted = 0;          // copies the parcels ask for (a scalar: no overflow)
    label heavy = 0;
    for (parcelType& p : cloud)
    {
        if (!p.active())
        {
            continue;       // stuck and kept (stuckParcels keep): deposited
        }
        scalar F = 1;
        forAll(regionCells_, r)
        {
            if (factor_[r] > F && regionCells_[r].test(p.cell()))
            {
                F = factor_[r];
            }
        }
        if (F <= 1)
        {
            continue;
        }
        const scalar n = p.nParticle()*p.mass()*F/mRef;
        if (!(n >= 1.5))
        {
            continue;
        }
        if (n >= maxCopies_ + 0.5)
        {
            ++heavy;
            continue;
        }
        const label k = label(n + 0.5);
        parcels.append(&p);
        nCopies.append(k);
        wanted += k - 1;
    }

    // 2. the cloud may hold at most maxParcels: the copies of this step share
    //    what is left of it, each processor in proportion to its demand (one
    //    reduction of both counts)
    vector2D counts(cloud.size(), wanted);
    reduce(counts, sumOp<vector2D>());
    const scalar room = max(scalar(0), scalar(maxParcels_) - counts.x());
    const bool capped = counts.y() > room;
    const scalar allowed =
        capped ? (counts.y() > 0 ? std::floor(room*wanted/counts.y()) : 0) : wanted;

    // 3. split in order while the copies fit; a parcel whose copies do not
    //    fit is left whole (unbiased either way: splitting never changes the
    //    expected deposit)
    label split = 0, copies = 0, left = 0;
    forAll(parcels, i)
    {
        parcelType& p = *parcels[i];
        const label n = nCopies[i];
        if (copies + n - 1 > allowed)
        {
            ++left;
            continue;
        }
        p.nParticle() /= n;
        p.tTurb() = GREAT;      // new turbulent fluctuation next step
        for (label k = 1; k < n; ++k)
        {
            cloud.addParticle(new parcelType(p));
        }
        ++split;
        copies += n - 1;
    }

    reduce(split, sumOp<label>());
    reduce(copies, sumOp<label>());
    reduce(left, sumOp<label>());
    reduce(heavy, sumOp<label>());
    if (split)
    {
        nSplit_ += split;
        nCopies_ += copies;
        Info<< "    parcelSplitting " << this->modelName() << ": "
            << split << " parcels split into " << copies + split
            << " (totals " << nSplit_ << ", +" << nCopies_ << ")"
            << endl;
    }
    if (capped && !capped_)
    {
        // said once each time the cap starts to bind
        if (room <= 0)
        {
            Info<< "    parcelSplitting " << this->modelName() << ": "
                << label(counts.x()) << " parcels >= maxParcels " << maxParcels_
                << ": no splitting while the cloud is that large" << endl;
        }
        else
        {
            Info<< "    parcelSplitting " << this->modelName() << ": " << left
                << " parcels left whole: their copies would take the cloud "
                << "past maxParcels " << maxParcels_ << endl;
        }
    }
    capped_ = capped;
    if (heavy && !heavyNoticed_)
    {
        Info<< "    parcelSplitting " << this->modelName() << ": " << heavy
            << " parcels left whole: heavier than maxCopies/F reference "
            << "masses, they would need more than maxCopies " << maxCopies_
            << " copies (said once)" << endl;
        heavyNoticed_ = true;
    }

    CloudFunctionObject<CloudType>::postEvolve();
}


template<class CloudType>
void Foam::ParcelSplitting<CloudType>::write()
{
    this->setModelProperty("nSplit", nSplit_);
    this->setModelProperty("nCopies", nCopies_);
}


// ************************************************************************* //
