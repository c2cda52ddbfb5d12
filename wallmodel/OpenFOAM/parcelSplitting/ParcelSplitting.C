/*---------------------------------------------------------------------------*\
  SnowWall: wallmodel/OpenFOAM/parcelSplitting (see ParcelSplitting.H)
\*---------------------------------------------------------------------------*/

#include "ParcelSplitting.H"
#include "treeBoundBox.H"
#include "Pstream.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
void Foam::ParcelSplitting<CloudType>::readRegions()
{
    const dictionary& dict = this->coeffDict();
    const PtrList<entry> entries(dict.lookup("regions"));
    if (entries.empty())
    {
        FatalIOErrorInFunction(dict)
            << "parcelSplitting: 'regions' is empty" << exit(FatalIOError);
    }

    const pointField& cc = this->owner().mesh().cellCentres();

    regionNames_.setSize(entries.size());
    regionCells_.setSize(entries.size());
    factor_.setSize(entries.size());

    forAll(entries, r)
    {
        if (!entries[r].isDict())
        {
            FatalIOErrorInFunction(dict)
                << "parcelSplitting: region entry '" << entries[r].keyword()
                << "' is not a dictionary { boxes (...); factor F; }"
                << exit(FatalIOError);
        }
        const dictionary& rd = entries[r].dict();
        regionNames_[r] = entries[r].keyword();

        const scalar F = rd.get<scalar>("factor");
        if (!(F >= 1) || !std::isfinite(F) || F > 1e6)
        {
            FatalIOErrorInFunction(rd)
                << "parcelSplitting: region " << regionNames_[r]
                << ": factor " << F << " must be in [1, 1e6]"
                << exit(FatalIOError);
        }
        factor_[r] = F;

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
            FatalIOErrorInFunction(rd)
                << "parcelSplitting: region " << regionNames_[r]
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
                FatalIOErrorInFunction(rd)
                    << "parcelSplitting: region " << regionNames_[r]
                    << ": box " << lo << " " << hi
                    << " needs min < max in x, y, z" << exit(FatalIOError);
            }
            bbs[b] = treeBoundBox(lo, hi);
        }
        if (bbs.empty())
        {
            FatalIOErrorInFunction(rd)
                << "parcelSplitting: region " << regionNames_[r]
                << ": needs 'box (min) (max);' or a non-empty"
                << " 'boxes ((min) (max) ...);'" << exit(FatalIOError);
        }

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
            "maxParcels", labelMax
        )
    ),
    nSplit_(0),
    nCopies_(0),
    capped_(false)
{
    if (maxParcels_ < 1)
    {
        FatalIOErrorInFunction(this->coeffDict())
            << "parcelSplitting: maxParcels " << maxParcels_
            << " must be >= 1" << exit(FatalIOError);
    }
    readRegions();
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
    nSplit_(ps.nSplit_),
    nCopies_(ps.nCopies_),
    capped_(ps.capped_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::ParcelSplitting<CloudType>::postEvolve()
{
    const scalar mRef = referenceMass();
    CloudType& cloud = this->owner();
    // the global count only when a cap is set (a reduction every step otherwise)
    const label nParcels =
    (
        maxParcels_ < labelMax
      ? returnReduce(cloud.size(), sumOp<label>())
      : label(0)
    );

    if (nParcels > maxParcels_ && !capped_)
    {
        Info<< "    parcelSplitting " << this->modelName() << ": "
            << nParcels << " parcels > maxParcels " << maxParcels_
            << ": no splitting while the cloud is that large" << endl;
    }
    capped_ = nParcels > maxParcels_;

    if (mRef > 0 && !capped_)
    {
        // find the parcels to split first: copies are added afterwards
        DynamicList<parcelType*> parcels;
        DynamicList<label> nCopies;
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
            if (n >= 1.5)
            {
                parcels.append(&p);
                nCopies.append(label(min(n, scalar(1e4)) + 0.5));
            }
        }

        label split = 0, copies = 0;
        forAll(parcels, i)
        {
            parcelType& p = *parcels[i];
            const label n = nCopies[i];
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
        if (split)
        {
            nSplit_ += split;
            nCopies_ += copies;
            Info<< "    parcelSplitting " << this->modelName() << ": "
                << split << " parcels split into " << copies + split
                << " (totals " << nSplit_ << ", +" << nCopies_ << ")"
                << endl;
        }
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
