/*---------------------------------------------------------------------------*\
  SnowWall: wallmodel/OpenFOAM/snowWallInteraction
-------------------------------------------------------------------------------
Description
    SnowWallInteraction: the output. info() at every output step: the
    per-patch totals (summed over the processors, plus those of the start
    time on a restart) and the counts by reason to the log, the time series
    postProcessing/<cloud>:snowWall/<startTime>/snowWall.dat; at a write
    time the totals into the cloud's properties (restart), reasons.dat and
    the stick records. Included by SnowWallInteraction.C.

\*---------------------------------------------------------------------------*/

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
void Foam::SnowWallInteraction<CloudType>::writeSeries
(
    const labelList& ni,
    const labelList& ns,
    const labelList& nb,
    const labelList& nr,
    const scalarList& md
)
{
    if (!Pstream::master())
    {
        return;
    }
    const Time& time = this->owner().mesh().time();
    if (!seriesPtr_.valid())
    {
        const fileName dir
        (
            time.globalPath()/"postProcessing"
           /(this->owner().name() + ":snowWall")
           /time.timeName(time.startTime().value())
        );
        mkDir(dir);
        seriesPtr_.reset(new OFstream(dir/"snowWall.dat"));
        OFstream& os = seriesPtr_();
        os.precision(12);
        os << "# time";
        const polyBoundaryMesh& bm = this->owner().mesh().boundaryMesh();
        for (const label patchi : snowPatches_)
        {
            const word& pn = bm[patchi].name();
            os  << ' ' << pn << ":impacts " << pn << ":sticks "
                << pn << ":bounces " << pn << ":ripoffs "
                << pn << ":depositedMass[kg]";
        }
        os << endl;
    }
    OFstream& os = seriesPtr_();
    os << time.value();
    forAll(ni, s)
    {
        os << ' ' << ni[s] << ' ' << ns[s] << ' ' << nb[s] << ' ' << nr[s]
           << ' ' << md[s];
    }
    os << endl;
}


template<class CloudType>
void Foam::SnowWallInteraction<CloudType>::writeReasons
(
    const labelList& ni,
    const labelList& nc
) const
{
    if (!Pstream::master())
    {
        return;
    }
    const Time& time = this->owner().mesh().time();
    const fileName dir
    (
        time.globalPath()/"postProcessing"
       /(this->owner().name() + ":snowWall")/time.timeName()
    );
    mkDir(dir);
    const fileName final(dir/"reasons.dat"), tmp(dir/".reasons.dat.tmp");
    const polyBoundaryMesh& bm = this->owner().mesh().boundaryMesh();
    const label nk = SWW_NCLASS + 1;
    {
        OFstream os(tmp);
        os  << "# snowWallInteraction: counts by reason at time " << time.timeName()
            << " (cumulative since the start of the case, all processors; on a snow"
            << " patch impacts = stuck + criterion + tangential + shear + probability,"
            << " where parcels escape impacts = escaped)"
            << nl << "# patch type impacts";
        for (label c = 0; c < nk; ++c)
        {
            os  << ' ' << (c < SWW_NCLASS ? sww_class_name(sww_class(c)) : "escaped");
        }
        os  << nl;
        labelList sum(nk + 1, 0);
        forAll(reportPatches_, r)
        {
            // a snow patch's impacts (the core's counter); where parcels
            // escape, the parcels that escaped there
            const label imp = r < snowPatches_.size() ? ni[r] : nc[nk*r + SWW_NCLASS];
            os  << bm[reportPatches_[r]].name() << ' '
                << (r < snowPatches_.size() ? "snow" : "escape") << ' ' << imp;
            sum[0] += imp;
            for (label c = 0; c < nk; ++c)
            {
                os  << ' ' << nc[nk*r + c];
                sum[c + 1] += nc[nk*r + c];
            }
            os  << nl;
        }
        os  << "total -";
        forAll(sum, c) os << ' ' << sum[c];
        os  << nl;
        if (!os.good())
        {
            FatalErrorInFunction
                << "snowWallInteraction: cannot write " << tmp << exit(FatalError);
        }
    }
    if (!Foam::mv(tmp, final))
    {
        FatalErrorInFunction
            << "snowWallInteraction: cannot rename " << tmp << " to " << final
            << exit(FatalError);
    }
}


template<class CloudType>
template<class T>
Foam::List<T> Foam::SnowWallInteraction<CloudType>::total
(
    const List<T>& local,
    const List<T>& start
)
{
    // sum over the processors, known on every processor, plus the start totals
    List<T> t(local);
    Pstream::listCombineGather(t, plusEqOp<T>());
    Pstream::listCombineScatter(t);
    forAll(t, i)
    {
        t[i] += start[i];
    }
    return t;
}


template<class CloudType>
void Foam::SnowWallInteraction<CloudType>::writeStickRecords()
{
    // the records since the last write, gathered on the master; every
    // processor takes part for every recorded patch
    const Time& time = this->owner().mesh().time();
    const polyBoundaryMesh& bm = this->owner().mesh().boundaryMesh();
    forAll(snowPatches_, s)
    {
        if (!recordSticks_[s]) continue;
        List<List<string>> all(Pstream::nProcs());
        all[Pstream::myProcNo()] = stickLines_[s];
        Pstream::gatherList(all);
        stickLines_[s].clear();
        if (!Pstream::master()) continue;
        const fileName dir
        (
            time.globalPath()/"postProcessing"/"lagrangian"
           /this->owner().name()/"snowWallSticks"/time.timeName()
        );
        mkDir(dir);
        // written whole to a temporary file, then renamed
        const word pn(bm[snowPatches_[s]].name());
        const fileName final(dir/(pn + ".post")), tmp(dir/("." + pn + ".post.tmp"));
        {
            OFstream os(tmp);
            os  << "# Time (position0 position1 position2) origProc origId"
                << " nParticle d rho" << nl;
            for (const List<string>& l : all)
            {
                for (const string& line : l)
                {
                    os  << line.c_str() << nl;
                }
            }
            if (!os.good())
            {
                FatalErrorInFunction
                    << "snowWallInteraction: cannot write " << tmp
                    << exit(FatalError);
            }
        }
        if (!mv(tmp, final))
        {
            FatalErrorInFunction
                << "snowWallInteraction: cannot rename " << tmp << " to "
                << final << exit(FatalError);
        }
    }
}

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::SnowWallInteraction<CloudType>::info(Ostream& os)
{
    if (!filmChecked_)
    {
        checkFilm(false);
    }
    PatchInteractionModel<CloudType>::info(os);

    const labelList ni(total(nImpact_, nImpact0_));
    const labelList ns(total(nStick_, nStick0_));
    const labelList nb(total(nBounce_, nBounce0_));
    const labelList nr(total(nRipoff_, nRipoff0_));
    const labelList no(total(nOutside_, nOutside0_));
    const scalarList md(total(massDeposit_, massDeposit0_));

    const polyBoundaryMesh& bm = this->owner().mesh().boundaryMesh();
    forAll(snowPatches_, s)
    {
        os  << "    snowWall: patch " << bm[snowPatches_[s]].name()
            << ": impacts " << ni[s] << ", sticks " << ns[s]
            << ", bounces " << nb[s] << ", ripoffs " << nr[s]
            << ", deposited mass " << md[s] << " kg"
            << " (" << no[s] << " impacts outside the fitted v_n range)" << nl;
    }
    writeSeries(ni, ns, nb, nr, md);

    // counts by reason per reported patch and in total
    const labelList nc(total(nReason_, nReason0_));
    const label nk = SWW_NCLASS + 1;
    labelList sum(nk, 0);
    label sumImpacts = 0;
    forAll(reportPatches_, r)
    {
        os  << "    snowWall: patch " << bm[reportPatches_[r]].name() << " by reason:";
        for (label c = 0; c < nk; ++c)
        {
            os  << (c ? ", " : " ")
                << (c < SWW_NCLASS ? sww_class_name(sww_class(c)) : "escaped")
                << ' ' << nc[nk*r + c];
            sum[c] += nc[nk*r + c];
        }
        os  << nl;
        sumImpacts += r < snowPatches_.size() ? ni[r] : nc[nk*r + SWW_NCLASS];
    }
    os  << "    snowWall: total: impacts " << sumImpacts << " by reason:";
    for (label c = 0; c < nk; ++c)
    {
        os  << (c ? ", " : " ")
            << (c < SWW_NCLASS ? sww_class_name(sww_class(c)) : "escaped") << ' ' << sum[c];
    }
    os  << nl;
    const label nStall = snowStallCount(stall_);
    if (nStall > 0)
    {
        os  << "    snowWall: " << nStall << " tracking step(s) ended by the"
            << " stall guard (wall hits that did not advance the step)" << nl;
    }

    if (covered_)
    {
        // faces bare / blending / covered, from the deposit field
        const volScalarField& dep = deposit();
        forAll(snowPatches_, s)
        {
            if (!buildUpOn_[s]) continue;
            const scalarField& f = dep.boundaryField()[snowPatches_[s]];
            label nBlend = 0, nCovered = 0;
            forAll(f, i)
            {
                if (f[i] >= coverMass_) ++nCovered;
                else if (f[i] > 0) ++nBlend;
            }
            reduce(nBlend, sumOp<label>());
            reduce(nCovered, sumOp<label>());
            const label nFaces =
                returnReduce(f.size(), sumOp<label>());
            os  << "    snowWall: patch " << bm[snowPatches_[s]].name()
                << ": faces covered " << nCovered << ", partly covered "
                << nBlend << ", of " << nFaces << nl;
        }
    }

    if (this->writeTime())
    {
        // global totals, the same on every processor (the properties
        // dictionary is read by the master and broadcast on restart)
        forAll(snowPatches_, s)
        {
            const word& pn = bm[snowPatches_[s]].name();
            this->setModelProperty(pn + ":impacts", ni[s]);
            this->setModelProperty(pn + ":sticks", ns[s]);
            this->setModelProperty(pn + ":bounces", nb[s]);
            this->setModelProperty(pn + ":ripoffs", nr[s]);
            this->setModelProperty(pn + ":outsideFitRange", no[s]);
            this->setModelProperty(pn + ":depositedMass", md[s]);
        }
        forAll(reportPatches_, r)
        {
            this->setModelProperty
            (
                bm[reportPatches_[r]].name() + ":byReason",
                labelList(SubList<label>(nc, nk, nk*r))
            );
        }
        writeReasons(ni, nc);
        writeStickRecords();
    }
}


// ************************************************************************* //
