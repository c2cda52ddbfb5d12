/*---------------------------------------------------------------------------*\
  SnowWall: wallmodel/OpenFOAM/snowWallInteraction
-------------------------------------------------------------------------------
Description
    SnowWallInteraction: the impacts. correct() for every parcel that hits
    a patch (by the patch's interaction type: none, rebound, stick, escape,
    snow) and impactSnow() for a snow patch: the impact in the wall frame,
    the wall shear stress, the draw u, the C core's decision (sww_decide,
    sww_decide_blend with build-up), the parcel's new velocity or its
    deposit, the counters. Included by SnowWallInteraction.C.

\*---------------------------------------------------------------------------*/

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
void Foam::SnowWallInteraction<CloudType>::uncountEscape(scalar mass)
{
    this->escapedMass_ -= mass;
    --this->escapedParcels_;
}


template<class CloudType>
Foam::scalar Foam::SnowWallInteraction<CloudType>::wallShearStress
(
    const polyPatch& pp,
    label facei
) const
{
    const fvMesh& mesh = this->owner().mesh();
    const volVectorField* tauPtr = mesh.findObject<volVectorField>(tauName_);
    if (!tauPtr)
    {
        FatalErrorInFunction
            << "snowWallInteraction: the shear gate is on but the field '"
            << tauName_ << "' does not exist. Add to system/controlDict:" << nl
            << "    functions { wallShearStress { type wallShearStress; "
            << "libs (\"libfieldFunctionObjects.so\"); patches ("
            << pp.name() << "); writeControl writeTime; } }" << nl
            << "(and real gradSchemes), or set shearGate { active false; }"
            << exit(FatalError);
    }
    const scalar t = mag(tauPtr->boundaryField()[pp.index()][facei]);
    if (t == 0)
    {
        // not filled yet (the function object computes it from the second
        // time step on, and only then sets its units): zero in any units
        return 0;
    }
    const dimensionSet& dims = tauPtr->dimensions();
    if (dims == dimPressure)
    {
        return t;
    }
    if (dims == dimVelocity*dimVelocity)
    {
        if (rhoAir_ <= 0)
        {
            FatalErrorInFunction
                << "snowWallInteraction: the field '" << tauName_
                << "' is kinematic [m2/s2] (incompressible solver): add "
                << "rhoAir <air density [kg/m3]>; to shearGate in "
                << this->coeffDict().name() << exit(FatalError);
        }
        return rhoAir_*t;
    }
    FatalErrorInFunction
        << "snowWallInteraction: the field '" << tauName_ << "' has units "
        << dims << ", expected [Pa] or [m2/s2]" << exit(FatalError);
    return 0;
}



// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
bool Foam::SnowWallInteraction<CloudType>::correct
(
    typename CloudType::parcelType& p,
    const polyPatch& pp,
    bool& keepParticle
)
{
    if (!filmChecked_)
    {
        checkFilm(false);
    }
    const label groupi = groupOfPatch_[pp.index()];
    if (groupi < 0)
    {
        return false;
    }
    // a parcel that the walls send back without letting it move: its step
    // ends where it is (after this hit is handled as any other)
    snowTrackingStall(stall_, p, "snowWallInteraction", word::null);

    vector& U = p.U();

    // Bookkeeping: the cloud (KinematicParcel::hitPatch) has already counted
    // a hit on an open patch (neither wall nor constraint) as escaped. A
    // parcel removed here without a deposit is an escape; one kept, or
    // deposited, is not.
    const scalar mp = p.mass()*p.nParticle();
    const bool open = openPatch_[pp.index()];

    switch (groupType_[groupi])
    {
        case PatchInteractionModel<CloudType>::itNone:
        {
            // the cloud removes it on an open patch (counted)
            if (open)
            {
                ++nReason_[(SWW_NCLASS + 1)*reportOfPatch_[pp.index()] + SWW_NCLASS];
            }
            return false;
        }
        case PatchInteractionModel<CloudType>::itRebound:
        {
            // as localInteraction
            if (open) uncountEscape(mp);
            keepParticle = true;
            p.active(true);
            vector nw, Up;
            this->owner().patchData(p, pp, nw, Up);
            U -= Up;
            const scalar Un = U & nw;
            const vector Ut = U - Un*nw;
            if (Un > 0)
            {
                U -= (1.0 + patchData_[groupi].e())*Un*nw;
            }
            U -= patchData_[groupi].mu()*Ut;
            U += Up;
            // On a symmetry plane the parcel that comes back is the mirror
            // image's: its turbulent fluctuation is mirrored too. Kept as it
            // was (as OpenFOAM's reflection does), a fluctuation pointing into
            // the plane drives the parcel back against it for the rest of its
            // eddy's life: parcels gather in the plane's first cells.
            if (isA<symmetryPlanePolyPatch>(pp) || isA<symmetryPolyPatch>(pp))
            {
                vector& uTurb = p.UTurb();
                uTurb -= 2*(uTurb & nw)*nw;
            }
            return true;
        }
        case PatchInteractionModel<CloudType>::itStick:
        {
            // as localInteraction
            if (open) uncountEscape(mp);
            keepParticle = true;
            p.active(false);
            U = Zero;
            return true;
        }
        case PatchInteractionModel<CloudType>::itEscape:
        {
            ++nReason_[(SWW_NCLASS + 1)*reportOfPatch_[pp.index()] + SWW_NCLASS];
            if (!open) this->addToEscapedParcels(mp);
            keepParticle = false;
            p.active(false);
            U = Zero;
            return true;
        }
        default:   // itSnow
            break;
    }

    // snow: deposited or kept in the cloud, so not an escape
    if (open) uncountEscape(mp);
    return impactSnow(p, pp, pp.whichFace(p.face()), keepParticle);
}


template<class CloudType>
bool Foam::SnowWallInteraction<CloudType>::impactSnow
(
    typename CloudType::parcelType& p,
    const polyPatch& pp,
    const label facei,
    bool& keepParticle
)
{
    const label s = slotOfPatch_[pp.index()];
    if (s < 0)
    {
        return false;
    }

    vector& U = p.U();
    const scalar mp = p.mass()*p.nParticle();

    // the C core decides, in the wall frame (patchData reads the parcel's
    // face; a parcel away from the wall, from the near-wall closure, takes
    // the face's normal and the wall's velocity there)
    vector nw, Up;
    if (p.face() >= 0 && pp.whichFace(p.face()) == facei)
    {
        this->owner().patchData(p, pp, nw, Up);
    }
    else
    {
        nw = pp.faceNormals()[facei];
        Up = Zero;
        const polyMesh& mesh = this->owner().mesh();
        if (mesh.moving())
        {
            const label gf = pp.start() + facei;
            const face& f = mesh.faces()[gf];
            const pointField& oldPts = mesh.oldPoints();
            const pointField& pts = mesh.points();
            const scalar dt = mesh.time().deltaTValue();
            Up = (f.centre(pts) - f.centre(oldPts))/dt;
        }
    }
    const vector Urel = U - Up;
    const scalar Un = Urel & nw;            // > 0: towards the wall
    const vector Ut = Urel - Un*nw;

    sww_impact in;
    in.d = p.d();
    in.vn = Un > 0 ? Un : 0;
    in.vt = mag(Ut);
    in.tau_w = shearOn_ ? wallShearStress(pp, facei) : 0;
    if (drawMatters_)
    {
        // fixed by the parcel and its impact: (seed, origin processor and
        // id, time index, impacts of the parcel before in this time step)
        const label ti = this->owner().mesh().time().timeIndex();
        if (ti != drawStep_)
        {
            drawsInStep_.clear();
            drawStep_ = ti;
        }
        const unsigned long long key =
            (static_cast<unsigned long long>(static_cast<unsigned int>(p.origProc())) << 32)
          | static_cast<unsigned int>(p.origId());
        const label k = drawsInStep_[key]++;
        in.u = sww_uniform_hash
        (
            static_cast<unsigned long long>(seed_), p.origProc(), p.origId(), ti, k
        );
    }
    else
    {
        in.u = 0.5;   // a sharp map: any u gives the same answer
    }

    // the patch's own bare-wall regime (the main one or a wallRegimes entry's)
    const sww_model* bare = slotModel_[s];
    sww_outcome out;
    int rc;
    if (covered_ && buildUpOn_[s])
    {
        // the face's own deposit decides how far it is covered
        const scalar w = sww_cover_fraction
        (
            deposit().boundaryField()[pp.index()][facei], coverMass_
        );
        rc = sww_decide_blend(bare, covered_, w, &in, &out);
    }
    else
    {
        rc = sww_decide(bare, &in, &out);
    }
    if (rc != SWW_OK)
    {
        FatalErrorInFunction
            << "snowWallInteraction: invalid impact on patch " << pp.name()
            << ": d " << in.d << " vn " << in.vn << " vt " << in.vt
            << " tau_w " << in.tau_w << exit(FatalError);
    }

    ++nImpact_[s];
    if (out.range != 0) ++nOutside_[s];
    // the slot is the report index of a snow patch (they come first)
    ++nReason_[(SWW_NCLASS + 1)*s + sww_outcome_class(&out)];

    if (debug)
    {
        // one line per impact (DebugSwitches { snowWallInteraction 1; })
        Pout<< "snowWallInteraction: impact patch " << pp.name() << " face "
            << facei << " x " << p.position() << " n " << nw << " U " << U
            << " Uwall " << Up << " d " << in.d << " vn " << in.vn << " vt " << in.vt
            << " u " << in.u << " parcel " << p.origProc() << ':' << p.origId()
            << " step " << this->owner().mesh().time().timeIndex() << " -> "
            << (
                   out.fate == SWW_STICK ? "stick"
                 : out.fate == SWW_BOUNCE ? "bounce" : "ripoff"
               )
            << endl;
    }

    if (out.fate == SWW_STICK)
    {
        ++nStick_[s];
        massDeposit_[s] += mp;
        const scalar area = this->owner().mesh().magSf().boundaryField()
            [pp.index()][facei];
        deposit().boundaryFieldRef()[pp.index()][facei] += mp/area;
        if (recordSticks_[s])
        {
            OStringStream rec;
            rec.precision(10);
            const point& x = p.position();
            rec << this->owner().mesh().time().value() << ' ' << x.x() << ' '
                << x.y() << ' ' << x.z() << ' ' << p.origProc() << ' '
                << p.origId() << ' ' << p.nParticle() << ' ' << p.d() << ' '
                << p.rho();
            stickLines_[s].append(rec.str());
        }
        keepParticle = !removeStuck_;
        p.active(false);
        U = Zero;
    }
    else
    {
        if (out.fate == SWW_BOUNCE) ++nBounce_[s]; else ++nRipoff_[s];
        keepParticle = true;
        p.active(true);
        const scalar UnNew = Un > 0 ? -out.e_n*Un : Un;
        U = Up + out.e_t*Ut + UnNew*nw;
    }
    return true;
}


// ************************************************************************* //
