/*---------------------------------------------------------------------------*\
    SnowWallInteraction - see SnowWallInteraction.H and doc/wallmodel.md.
\*---------------------------------------------------------------------------*/

#include "SnowWallInteraction.H"
#include "fvMesh.H"
#include "Time.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "patchInteractionData.H"
#include "emptyPolyPatch.H"
#include "processorPolyPatch.H"
#include "wallPolyPatch.H"
#include "regionModel.H"
#include "snowMachineLimits.H"
#include "OStringStream.H"
#include <fstream>
#include <initializer_list>
#include <cctype>
#include <cmath>
#include <cstdlib>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{
namespace snowWallDetail
{

//- The files a dictionary file reads: itself and, recursively (depth 4),
//  the files its #include / #includeIfPresent lines name (relative to the
//  including file's folder, environment variables expanded)
inline void dictFiles(const fileName& f, DynamicList<fileName>& out, int depth)
{
    if (depth > 4 || !isFile(f) || out.found(f))
    {
        return;
    }
    out.append(f);
    std::ifstream in(f.c_str());
    std::string line;
    while (std::getline(in, line))
    {
        // anywhere in the line, not after a // comment: an entry may hold
        // its include on one line, roughABS { patches (...); #include "x" }
        const std::string::size_type h = line.find("#include");
        const std::string::size_type c = line.find("//");
        if (h == std::string::npos || (c != std::string::npos && c < h))
        {
            continue;
        }
        if (line.compare(h, 11, "#includeEtc") == 0) continue;
        const std::string::size_type q0 = line.find('"', h);
        const std::string::size_type q1 =
            q0 == std::string::npos ? q0 : line.find('"', q0 + 1);
        if (q1 == std::string::npos) continue;
        fileName inc(line.substr(q0 + 1, q1 - q0 - 1));
        inc.expand();
        if (!inc.isAbsolute()) inc = f.path()/inc;
        dictFiles(inc, out, depth + 1);
    }
}

//- Line n (1-based) of a file's lines holds keyword key (as a word)
inline bool lineHasKey(const List<std::string>& lines, label n, const std::string& key)
{
    if (n < 1 || n > lines.size()) return false;
    const std::string& l = lines[n - 1];
    for
    (
        std::string::size_type k = l.find(key);
        k != std::string::npos;
        k = l.find(key, k + 1)
    )
    {
        const std::string::size_type e = k + key.size();
        const bool before =
            k == 0 || !(std::isalnum(static_cast<unsigned char>(l[k-1])) || l[k-1] == '_');
        const bool after =
            e == l.size() || !(std::isalnum(static_cast<unsigned char>(l[e])) || l[e] == '_');
        if (before && after) return true;
    }
    return false;
}

//- The line of entry e (1-based, in one file's lines) shows e's first value:
//  the number (to 1e-12 relative) or the word right after the keyword, a
//  list's first item after its '('; entries without a plain first value pass
inline bool lineHasValue(const List<std::string>& lines, const entry& e)
{
    const label n = e.startLineNumber();
    if (n < 1 || n > lines.size()) return false;
    ITstream& is = e.stream();
    if (is.empty()) return true;
    label k = 0;
    while (k < is.size() && is[k].isPunctuation()) ++k;   // a list's '('
    if (k >= is.size()) return true;
    const token& t = is[k];
    const std::string& l = lines[n - 1];
    std::string::size_type p = l.find(std::string(e.keyword()));
    if (p == std::string::npos) return false;
    p += std::string(e.keyword()).size();
    while (p < l.size() && (std::isspace(static_cast<unsigned char>(l[p])) || l[p] == '(')) ++p;
    if (t.isNumber())
    {
        const char* b = l.c_str() + p;
        char* end = nullptr;
        const double v = std::strtod(b, &end);
        const double x = t.number();
        if (end == b || !std::isfinite(v) || !std::isfinite(x)) return false;
        if (v == x) return true;
        // relative, without a difference that could overflow (OpenFOAM traps it)
        const double m = std::max(std::fabs(v), std::fabs(x));
        return std::fabs(v/m - x/m) <= 1e-12;
    }
    if (t.isWord() || t.isString())
    {
        const std::string w(t.isWord() ? std::string(t.wordToken()) : std::string(t.stringToken()));
        return l.find(w, p) != std::string::npos;
    }
    return true;
}

//- The file dictionary d was read from: its name is <file>.<scope>..., so
//  the longest '.'-cut prefix of the name that is a file (else the name)
inline fileName dictFile(const dictionary& d)
{
    std::string n(d.name());
    while (!n.empty())
    {
        if (isFile(n)) return fileName(n);
        const std::string::size_type k = n.rfind('.');
        if (k == std::string::npos || k == 0) break;
        n.erase(k);
    }
    return fileName(d.name());
}

//- The file that holds the keys of dictionary block d. OpenFOAM keeps an
//  entry's line number but names it after the dictionary scope, so the file
//  of a block read from an #included regime.coeffs is found again here:
//  among the dictionary's file and the files it #includes (the included
//  ones first), the first whose lines hold every key of d at its line; else
//  the first that holds key `key` at line `line`; else the dictionary's file.
inline fileName blockFile(const dictionary& d, const std::string& key, label line)
{
    const fileName top(dictFile(d));
    DynamicList<fileName> files;
    dictFiles(top, files, 0);
    List<List<std::string>> text(files.size());
    forAll(files, i)
    {
        std::ifstream in(files[i].c_str());
        DynamicList<std::string> lines;
        std::string l;
        while (std::getline(in, l)) lines.append(l);
        text[i].transfer(lines);
    }
    // every key of d at its line in file j, and with values = 1 the first
    // value as well: two regime files written by snowregime hold the same
    // keys at the same lines, and an error in the main regime named the one
    // a wallRegimes or buildUp entry included (issue 22)
    auto holdsBlock = [&](label j, bool values)
    {
        bool all = false;
        for (const entry& e : d)
        {
            if (e.isDict()) continue;
            all = lineHasKey(text[j], e.startLineNumber(), e.keyword());
            if (all && values) all = lineHasValue(text[j], e);
            if (!all) break;
        }
        return all;
    };
    forAllReverse(files, i)
    {
        if (holdsBlock(i, true)) return files[i];
    }
    forAllReverse(files, i)
    {
        if (holdsBlock(i, false)) return files[i];
    }
    forAllReverse(files, i)
    {
        if (!key.empty() && lineHasKey(text[i], line, key)) return files[i];
    }
    return top;
}

//- FatalIOError located at entry e of dictionary d (or at d itself when e
//  is null): the file that holds the lines (blockFile) and their numbers
inline OSstream& fatalAt(const dictionary& d, const entry* e)
{
    const label l0 = e ? e->startLineNumber() : d.startLineNumber();
    const label l1 = e ? e->endLineNumber() : d.endLineNumber();
    return FatalIOError
    (
        "snowWallInteraction", __FILE__, __LINE__,
        blockFile(d, e ? std::string(e->keyword()) : std::string(), l0), l0, l1
    );
}

//- A regime file #included into the cloud properties gives each key once:
//  OpenFOAM merges a repeated key or block silently (the later wins), the C
//  loader (snowregime, the other hosts) refuses it, so the same file would
//  mean two things (hostile sweep cases 524, 525 of issue 22). The file is
//  read again on its own with OpenFOAM's inputMode error; its FatalIOError
//  is caught and given again with the file, the line and the key.
inline void checkNoDuplicates(const fileName& f)
{
    const entry::inputMode oldMode = entry::globalInputMode;
    const bool oldThrow = FatalIOError.throwExceptions(true);
    entry::globalInputMode = entry::inputMode::ERROR;
    string msg;
    string file;
    label line = -1;
    try
    {
        IFstream is(f);
        // the constructor with a parent: the top-level one resets the mode
        dictionary d(fileName("regimeFile"), dictionary::null, is);
    }
    catch (const Foam::IOerror& err)
    {
        msg = err.message();
        file = err.ioFileName();
        line = err.ioStartLineNumber();
    }
    catch (const Foam::error& err)   // any other: restored below, then given
    {
        msg = err.message();
    }
    entry::globalInputMode = oldMode;
    FatalIOError.throwExceptions(oldThrow);
    if (!msg.empty())
    {
        FatalIOError
        (
            "snowWallInteraction", __FILE__, __LINE__,
            file.empty() ? f : fileName(file), line, line
        )   << "snowWallInteraction: regime file " << f.c_str() << ": " << msg.c_str()
            << " (a regime file gives each key and the regime block once: "
            << "OpenFOAM would merge a repeated one, the later winning, while "
            << "the C loader of snowregime and the other hosts refuses it)"
            << exit(FatalIOError);
    }
}

//- Number `key` of dictionary d, read and checked before it is used: a
//  finite value in [lo, hi] (in (lo, hi] with openLo), else a FatalIOError
//  at the entry that names the key, its sub-dictionary, the value and the
//  accepted range. isfinite comes first: an ordered comparison of a NaN
//  raises FE_INVALID, which OpenFOAM traps (SIGFPE, no message).
inline scalar checkedNumber
(
    const dictionary& d,
    const word& key,
    scalar lo,
    scalar hi,
    const char* unit,
    const char* what,
    bool openLo = false
)
{
    const scalar v = d.get<scalar>(key);    // a missing / unreadable value: OpenFOAM's error
    if (!std::isfinite(v) || v < lo || (openLo && v == lo) || v > hi)
    {
        fatalAt(d, d.findEntry(key, keyType::LITERAL))
            << "snowWallInteraction: " << d.dictName() << ": " << key << ' ' << v
            << " is outside the accepted range " << (openLo ? '(' : '[') << lo
            << ", " << hi << "] " << unit << " (" << what << ")"
            << exit(FatalIOError);
    }
    return v;
}

//- Every key of dictionary d is one of `allowed`, else a FatalIOError at the
//  entry naming the key, the dictionary and the accepted keys: a misspelt
//  key (coverDiamter, slidLength) or one the chosen model does not use
//  (vtMax with the regime gate) would otherwise be ignored without a word
inline void checkKeys
(
    const dictionary& d,
    std::initializer_list<const char*> allowed,
    const std::string& what,
    const char* hint = ""
)
{
    for (const entry& e : d)
    {
        const std::string k(e.keyword());
        bool ok = false;
        for (const char* a : allowed)
        {
            if (k == a) { ok = true; break; }
        }
        if (ok) continue;
        OSstream& os = fatalAt(d, &e);
        os  << "snowWallInteraction: " << what.c_str() << ": unknown key '"
            << k.c_str() << "'" << hint << "; the accepted keys are";
        for (const char* a : allowed) os << ' ' << a;
        os  << exit(FatalIOError);
    }
}

//- A patch-pattern list that is given is not empty: an empty list would
//  apply to no patch without a word
inline void checkNotEmpty(const dictionary& d, const wordRes& sel, const std::string& what)
{
    if (sel.empty())
    {
        fatalAt(d, d.findEntry("patches", keyType::LITERAL))
            << "snowWallInteraction: " << what.c_str() << ": the patches list "
            << "is empty (give at least one patch name or pattern, or leave "
            << "the entry out)" << exit(FatalIOError);
    }
}

//- The keys of snowWallInteractionCoeffs and of its sub-dictionaries, by
//  the model each names (doc/wallmodel.md), checked before anything is set
//  up; a sub-dictionary given as a value is an error, not "no gate"
inline void checkCoeffKeys(const dictionary& cd)
{
    checkKeys
    (
        cd,
        {
            "patches", "regime", "stuckParcels", "reboundTangential", "rebound",
            "randomSeed", "stickRecords",
            "tangentialGate", "shearGate", "buildUp", "wallRegimes"
        },
        std::string(cd.dictName())
    );
    for (const char* sub : {"tangentialGate", "shearGate", "buildUp", "wallRegimes"})
    {
        const entry* e = cd.findEntry(sub, keyType::LITERAL);
        if (e && !e->isDict())
        {
            fatalAt(cd, e)
                << "snowWallInteraction: " << sub << " is not a sub-dictionary "
                << "{ ... }" << exit(FatalIOError);
        }
    }
    if (cd.isDict("tangentialGate"))
    {
        const dictionary& g = cd.subDict("tangentialGate");
        const word model(g.lookupOrDefault<word>("model", "constant"));
        if (model == "regime")
        {
            checkKeys
            (
                g, {"active", "model", "slideLength", "vtTable"},
                "tangentialGate (model regime)",
                " (the regime gate takes d_crit(v_n, v_t) from the oblique "
                "table: vtMax, dRef and exponent belong to model constant)"
            );
        }
        else
        {
            checkKeys
            (
                g, {"active", "model", "vtMax", "dRef", "exponent"},
                "tangentialGate (model constant)"
            );
        }
    }
    if (cd.isDict("shearGate"))
    {
        const dictionary& g = cd.subDict("shearGate");
        const word model(g.lookupOrDefault<word>("model", "adhesion"));
        if (model == "constant")
        {
            checkKeys
            (
                g, {"active", "model", "tauCrit", "field", "rhoAir"},
                "shearGate (model constant)"
            );
        }
        else
        {
            checkKeys
            (
                g, {"active", "model", "roughnessFactor", "field", "rhoAir"},
                "shearGate (model adhesion)"
            );
        }
    }
    if (cd.isDict("buildUp"))
    {
        checkKeys
        (
            cd.subDict("buildUp"),
            {"active", "regime", "coverMass", "coverDiameter", "patches"},
            "buildUp"
        );
    }
    if (cd.isDict("wallRegimes"))
    {
        for (const entry& e : cd.subDict("wallRegimes"))
        {
            if (e.isDict())
            {
                checkKeys
                (
                    e.dict(), {"patches", "regime"},
                    "wallRegimes entry '" + std::string(e.keyword()) + "'"
                );
            }
        }
    }
}

//- Accepted ranges of buildUp's covering mass (doc/wallmodel.md): positive
//  (any small value: the cover fraction compares before it divides, so
//  nothing overflows) and at most a 0.1 m diameter (the kernel's largest) or
//  1e4 kg/m2 (one monolayer of 0.1 m ice spheres is 56 kg/m2)
static const scalar coverDMax = 0.1;
static const scalar coverMassMax = 1e4;

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

//- Whether the shear gate's field will be there at the first impact: it is
//  registered now, or it can be read from the start time's folder, or a
//  function object of system/controlDict makes it (a wallShearStress entry
//  makes "wallShearStress"; any entry whose 'result' names it is taken at
//  its word). Checked at set-up, before the function objects
//  start and write anything (hostile sweep case 496 of issue 22).
inline bool shearFieldProvided(const fvMesh& mesh, const word& name)
{
    if (mesh.foundObject<volVectorField>(name))
    {
        return true;
    }
    IOobject io
    (
        name, mesh.time().timeName(), mesh,
        IOobject::MUST_READ, IOobject::NO_WRITE, false
    );
    if (io.typeHeaderOk<volVectorField>(false))
    {
        return true;
    }
    const dictionary& cd = mesh.time().controlDict();
    if (!cd.isDict("functions"))
    {
        return false;
    }
    for (const entry& e : cd.subDict("functions"))
    {
        if (!e.isDict())
        {
            continue;
        }
        const dictionary& fd = e.dict();
        const word type(fd.lookupOrDefault<word>("type", word::null));
        if (type == "wallShearStress" && name == "wallShearStress")
        {
            return true;
        }
        if (fd.lookupOrDefault<word>("result", word::null) == name)
        {
            return true;
        }
    }
    return false;
}

} // End namespace snowWallDetail
} // End namespace Foam


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
const Foam::dictionary&
Foam::SnowWallInteraction<CloudType>::checkedPatches
(
    const polyMesh& mesh,
    const dictionary& coeffs
)
{
    // patchInteractionDataList (read next) only warns about a pattern that
    // matches nothing and blames "local patch interaction" for a patch
    // without an entry: both are errors here, naming the file
    // the first thing read of the coefficients: every key known
    snowWallDetail::checkCoeffKeys(coeffs);
    const polyBoundaryMesh& bm = mesh.boundaryMesh();
    const List<patchInteractionData> items(coeffs.lookup("patches"));
    if (items.empty())
    {
        snowWallDetail::fatalAt(coeffs, coeffs.findEntry("patches", keyType::LITERAL))
            << "snowWallInteraction: the patches list is empty: give every "
            << "boundary patch a type (snow, rebound, stick, escape or none)"
            << exit(FatalIOError);
    }

    // the first entry that takes each patch (patchInteractionDataList's order)
    labelList first(bm.size(), -1);
    forAll(items, i)
    {
        const keyType& key = items[i].patchName();
        const labelList ids(bm.indices(key));
        if (ids.empty())
        {
            FatalIOErrorInFunction(coeffs)
                << "snowWallInteraction: patches entry " << key << " (type "
                << items[i].interactionTypeName() << ") matches no patch of "
                << "the mesh (misspelt?); the patches are " << bm.names()
                << exit(FatalIOError);
        }
        for (const label id : ids)
        {
            if (first[id] < 0) first[id] = i;
        }
    }

    DynamicList<label> missing;
    forAll(bm, patchi)
    {
        const polyPatch& pp = bm[patchi];
        if (!pp.coupled() && !isA<emptyPolyPatch>(pp) && first[patchi] < 0)
        {
            missing.append(patchi);
        }
    }
    if (missing.size())
    {
        FatalIOErrorInFunction(coeffs)
            << "snowWallInteraction: no entry of patches (...) takes the patch";
        for (const label patchi : missing)
        {
            FatalIOError
                << ' ' << bm[patchi].name() << " (" << bm[patchi].type() << ')';
        }
        FatalIOError
            << ": add an entry for each, e.g. " << bm[missing[0]].name()
            << " { type snow; }, or a last catch-all \".*\" { type none; }"
            << exit(FatalIOError);
    }

    // a wall that another name's escape/none entry takes: a catch-all (or a
    // group) swallowing a wall whose own name was left out or misspelt; and
    // escape on a symmetry, wedge or cyclic patch, which OpenFOAM would
    // reflect or pass on (type none)
    forAll(bm, patchi)
    {
        const polyPatch& pp = bm[patchi];
        if (first[patchi] < 0) continue;
        const patchInteractionData& it = items[first[patchi]];
        const word& t = it.interactionTypeName();
        if
        (
            t == "escape"
         && (pp.coupled() || polyPatch::constraintType(pp.type()))
         && !isA<processorPolyPatch>(pp)
        )
        {
            WarningInFunction
                << "snowWallInteraction: " << pp.type() << " patch "
                << pp.name() << " takes type escape from the entry "
                << it.patchName() << " of " << snowWallDetail::dictFile(coeffs)
                << ": parcels reaching it are removed instead of "
                << (pp.coupled() ? "passed on" : "reflected")
                << ". Give it type none (OpenFOAM's own " << pp.type()
                << " treatment)" << endl;
        }
        if (!isA<wallPolyPatch>(pp)) continue;
        if ((t == "escape" || t == "none") && it.patchName() != pp.name())
        {
            WarningInFunction
                << "snowWallInteraction: wall patch " << pp.name()
                << " is taken by the entry " << it.patchName() << " (type "
                << t << ") of " << snowWallDetail::dictFile(coeffs)
                << ": parcels reaching it "
                << (t == "escape" ? "leave the cloud" : "pass through")
                << " and no snow settles there. Name the patch in patches "
                << "(...) before that entry if it is a wall the snow meets"
                << endl;
        }
    }
    return coeffs;
}


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
        << snowWallDetail::dictFile(sm)
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
        snowWallDetail::fatalAt(cd, cd.findEntry("patches", keyType::LITERAL))
            << "snowWallInteraction: every snow patch " << taken << " is a "
            << "patch of the surface film (" << film.type() << ", region "
            << film.regionMesh().name() << "): the cloud's surfaceFilmModel "
            << fm << " (interactionType " << it << ") takes every parcel that "
            << "hits it before the patch interaction model, so "
            << "snowWallInteraction would decide no impact and deposit "
            << "nothing. Give those patches type none (the film decides them) "
            << "or set  surfaceFilmModel none;  in subModels of "
            << snowWallDetail::dictFile(sm) << exit(FatalIOError);
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
        snowWallDetail::fatalAt(cd, e)
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
        snowWallDetail::fatalAt(cd, e)
            << "snowWallInteraction: stickRecords: the records held between "
            << "writes may need up to " << mem/GB << " GB of memory ("
            << std::floor(nMax) << " sticks x " << recMem
            << " bytes, an upper bound), more than 80 % of the "
            << avail/GB << " GB available (MemAvailable of /proc/meminfo): "
            << "record fewer patches or write more often" << exit(FatalIOError);
    }
}


template<class CloudType>
void Foam::SnowWallInteraction<CloudType>::uncountEscape(scalar mass)
{
    this->escapedMass_ -= mass;
    --this->escapedParcels_;
}


template<class CloudType>
void Foam::SnowWallInteraction<CloudType>::check
(
    const sww_model* m,
    int rc,
    const dictionary& dict,
    const entry* e
) const
{
    if (rc != SWW_OK)
    {
        snowWallDetail::fatalAt(dict, e)
            << "snowWallInteraction: " << context_.c_str() << sww_errmsg(m)
            << exit(FatalIOError);
    }
}


template<class CloudType>
void Foam::SnowWallInteraction<CloudType>::readRegime
(
    sww_model* m,
    const dictionary& regimeDict
)
{
    // Every entry goes through the C core's setters: the contract of
    // doc/regime-coeffs.md is checked once, in C.
    sww_regime_clear(m);
    for (const entry& e : regimeDict)
    {
        if (e.isDict())
        {
            continue;
        }
        const std::string key(e.keyword());
        ITstream& is = e.stream();
        if (is.empty())
        {
            continue;
        }
        const token& t0 = is[0];
        int rc = SWW_OK;
        if (t0.isNumber() && is.size() == 1)
        {
            rc = sww_regime_number(m, key.c_str(), t0.number());
        }
        else if ((t0.isWord() || t0.isString()) && is.size() == 1)
        {
            const std::string w(t0.isWord() ? t0.wordToken() : t0.stringToken());
            rc = sww_regime_word(m, key.c_str(), w.c_str());
        }
        else if (t0.isPunctuation() && t0.pToken() == token::BEGIN_LIST)
        {
            scalarList vals;
            is >> vals;
            rc = sww_regime_list(m, key.c_str(), vals.cdata(), vals.size());
        }
        else
        {
            snowWallDetail::fatalAt(regimeDict, &e)
                << "snowWallInteraction: regime key '" << e.keyword()
                << "': cannot read value " << is << exit(FatalIOError);
        }
        check(m, rc, regimeDict, &e);
    }
    // the C core's message starts with the origin, the dictionary's keyword;
    // check() adds the file and lines (read only on an error)
    const std::string origin(regimeDict.dictName());
    check(m, sww_regime_commit(m, origin.c_str()), regimeDict);
    // an #included regime file: no repeated key or block (an inline regime
    // block follows OpenFOAM's convention of its dictionary: merged)
    const fileName f(snowWallDetail::blockFile(regimeDict, std::string(), -1));
    if (f != snowWallDetail::dictFile(regimeDict))
    {
        snowWallDetail::checkNoDuplicates(f);
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
    check
    (
        m,
        sww_set_rebound_tangential
        (
            m, cd.lookupOrDefault<scalar>("reboundTangential", 1.0)
        ),
        cd
    );

    // The rebound of a bounce (issue 23): the kernel's tables of the regime
    // file when it has them (auto), required (table), or the classic
    // Thornton / constant e_n with reboundTangential (classic)
    {
        const word rb(cd.lookupOrDefault<word>("rebound", "auto"));
        const int code =
            rb == "auto" ? SWW_REBOUND_AUTO
          : rb == "table" ? SWW_REBOUND_TABLE
          : rb == "classic" ? SWW_REBOUND_CLASSIC
          : -1;
        if (code < 0)
        {
            snowWallDetail::fatalAt(cd, cd.findEntry("rebound", keyType::LITERAL))
                << "snowWallInteraction: rebound '" << rb
                << "' is not auto, table or classic" << exit(FatalIOError);
        }
        check(m, sww_set_rebound_model(m, code), cd, cd.findEntry("rebound", keyType::LITERAL));
    }

    if (cd.isDict("tangentialGate"))
    {
        const dictionary& g = cd.subDict("tangentialGate");
        if (g.lookupOrDefault<Switch>("active", true))
        {
            const word model(g.lookupOrDefault<word>("model", "constant"));
            if (model == "constant")
            {
                check
                (
                    m,
                    sww_set_tangential_gate
                    (
                        m,
                        g.get<scalar>("vtMax"),
                        g.lookupOrDefault<scalar>("dRef", 5e-5),
                        g.lookupOrDefault<scalar>("exponent", 0.0)
                    ),
                    g
                );
            }
            else if (model == "regime")
            {
                // d_crit(v_n, v_t) from the regime's oblique table
                // (snowregime map --vt 0,... --max-slide S), or a rough
                // wall's stick probability over v_t (snowregime map --set
                // wall=lattice --vt 0,...: issue 24)
                check(m, sww_set_tangential_regime(m), g);
                const bool roughVt = !sww_oblique_table(m, nullptr, nullptr);
                // the criterion's slide length, when the case states it,
                // must be the one the table was made with (the C core checks
                // it: a table without obliqueSlide is an error, not a NaN)
                // vtTable: the tangential speeds a case makes the table with
                // (tutorials/wedge/Allrun runs snowregime map --vt from it):
                // the table in use must have as many
                const entry* te = g.findEntry("vtTable", keyType::LITERAL);
                if (te)
                {
                    const scalarList vt(g.get<scalarList>("vtTable"));
                    size_t nvt = 0;
                    if (roughVt) nvt = sww_probability_vt(m, nullptr);
                    else sww_oblique_table(m, &nvt, nullptr);
                    if (size_t(vt.size()) != nvt)
                    {
                        snowWallDetail::fatalAt(g, te)
                            << "snowWallInteraction: tangentialGate vtTable has "
                            << vt.size() << " speeds, the regime's "
                            << (roughVt ? "stick-probability table " : "oblique table ")
                            << nvt << (roughVt ? " (probabilityVt)" : " (obliqueVt)")
                            << ": the coefficients were made "
                            << "with another list (rerun snowregime map --vt)"
                            << exit(FatalIOError);
                    }
                }
                const entry* se = g.findEntry("slideLength", keyType::LITERAL);
                if (se && roughVt)
                {
                    // a rough wall's stick is decided by energy (the sphere
                    // can never leave), with no slide criterion: the length
                    // is the flat regimes' (the same gate dictionary)
                    Info<< "snowWallInteraction: tangentialGate slideLength is "
                        << "not used by a rough wall's stick probability over "
                        << "v_t (its stick: the sphere can never leave)" << endl;
                }
                else if (se)
                {
                    check
                    (
                        m,
                        sww_check_oblique_slide(m, g.get<scalar>("slideLength")),
                        g,
                        se
                    );
                }
            }
            else
            {
                FatalIOErrorInFunction(g)
                    << "snowWallInteraction: tangentialGate model '" << model
                    << "' is not constant or regime" << exit(FatalIOError);
            }
        }
    }

    if (cd.isDict("shearGate"))
    {
        const dictionary& g = cd.subDict("shearGate");
        if (g.lookupOrDefault<Switch>("active", true))
        {
            const word model(g.lookupOrDefault<word>("model", "adhesion"));
            if (model == "adhesion")
            {
                check
                (
                    m,
                    sww_set_shear_gate_adhesion
                    (
                        m, g.lookupOrDefault<scalar>("roughnessFactor", 1.0)
                    ),
                    g
                );
            }
            else if (model == "constant")
            {
                check
                (
                    m,
                    sww_set_shear_gate_constant(m, g.get<scalar>("tauCrit")),
                    g
                );
            }
            else
            {
                FatalIOErrorInFunction(g)
                    << "snowWallInteraction: shearGate model '" << model
                    << "' is not adhesion or constant" << exit(FatalIOError);
            }
            shearOn_ = true;
            tauName_ = g.lookupOrDefault<word>("field", "wallShearStress");
            if
            (
               !snowWallDetail::shearFieldProvided
                (
                    this->owner().mesh(), tauName_
                )
            )
            {
                FatalIOErrorInFunction(g)
                    << "snowWallInteraction: shearGate: the field '"
                    << tauName_ << "' is not registered, not in the "
                    << "start time's folder and made by no function object "
                    << "of system/controlDict (a 'wallShearStress' entry of "
                    << "type wallShearStress makes the field wallShearStress;"
                    << " an entry whose 'result' names it is taken too). "
                    << "Add to system/controlDict:" << nl
                    << "    functions { wallShearStress { type wallShearStress;"
                    << " libs (\"libfieldFunctionObjects.so\");"
                    << " writeControl writeTime; } }" << nl
                    << "or set shearGate { active false; }"
                    << exit(FatalIOError);
            }
            // checked here, not at the first impact: a huge value would
            // overflow rhoAir*tau there (SIGFPE under OpenFOAM's traps)
            rhoAir_ =
                g.found("rhoAir", keyType::LITERAL)
              ? snowWallDetail::checkedNumber
                (
                    g, "rhoAir", 1e-6, 1e4, "kg/m3",
                    "the air density that turns a kinematic wall shear stress into Pa"
                )
              : -1.0;
        }
    }
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
        snowWallDetail::checkNotEmpty
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
        readRegime(m, ed.subDict("regime"));
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
    readRegime(model_, cd.subDict("regime"));

    const word stuck(cd.lookupOrDefault<word>("stuckParcels", "remove"));
    if (stuck == "remove")
    {
        removeStuck_ = true;
    }
    else if (stuck == "keep")
    {
        removeStuck_ = false;
    }
    else
    {
        FatalIOErrorInFunction(cd)
            << "snowWallInteraction: stuckParcels '" << stuck
            << "' is not remove or keep" << exit(FatalIOError);
    }

    applyGates(model_, cd);

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
            readRegime(covered_, b.subDict("regime"));
            applyGates(covered_, cd);
            // every number checked before it is used (a non-positive one
            // made a NaN whose comparison OpenFOAM trapped as SIGFPE)
            scalar dCover = -1;
            const bool hasMass = b.found("coverMass", keyType::LITERAL);
            const bool hasD = b.found("coverDiameter", keyType::LITERAL);
            if (hasMass && hasD)
            {
                snowWallDetail::fatalAt(b, b.findEntry("coverDiameter", keyType::LITERAL))
                    << "snowWallInteraction: buildUp: give coverDiameter or "
                    << "coverMass, not both (coverMass would be used, "
                    << "coverDiameter ignored)" << exit(FatalIOError);
            }
            if (hasMass)
            {
                coverMass_ = snowWallDetail::checkedNumber
                (
                    b, "coverMass", 0, snowWallDetail::coverMassMax, "kg/m2",
                    "the covering mass per area of a face", true
                );
            }
            else if (hasD)
            {
                dCover = snowWallDetail::checkedNumber
                (
                    b, "coverDiameter", 0, snowWallDetail::coverDMax, "m",
                    "the mean particle diameter: one monolayer covers a face", true
                );
                const scalar rho = this->owner().constProps().rho0();
                coverMass_ = sww_monolayer_mass(rho, dCover);
                if
                (
                    !std::isfinite(coverMass_)
                 || coverMass_ <= 0
                 || coverMass_ > snowWallDetail::coverMassMax
                )
                {
                    snowWallDetail::fatalAt(b, b.findEntry("coverDiameter", keyType::LITERAL))
                        << "snowWallInteraction: buildUp: coverDiameter " << dCover
                        << " m with the cloud's particle density rho0 " << rho
                        << " kg/m3 (constantProperties) gives a covering mass "
                        << coverMass_ << " kg/m2 outside the accepted range (0, "
                        << snowWallDetail::coverMassMax << "] kg/m2: check rho0, "
                        << "or give coverMass directly" << exit(FatalIOError);
                }
            }
            else
            {
                FatalIOErrorInFunction(b)
                    << "snowWallInteraction: buildUp: give coverDiameter (the mean "
                    << "particle diameter [m]: one monolayer covers a face) or "
                    << "coverMass [kg/m2]" << exit(FatalIOError);
            }
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

    // Interaction type of every patch group
    groupType_.setSize(patchData_.size());
    forAll(patchData_, groupi)
    {
        const word& t = patchData_[groupi].interactionTypeName();
        if (t == "none") groupType_[groupi] = 0;
        else if (t == "rebound") groupType_[groupi] = 1;
        else if (t == "stick") groupType_[groupi] = 2;
        else if (t == "escape") groupType_[groupi] = 3;
        else if (t == "snow") groupType_[groupi] = 4;
        else
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
        if (groupi >= 0 && groupType_[groupi] == 4)
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
    const label n = snowPatches_.size();

    // the snow patches with the build-up feedback: buildUp/patches, or all
    buildUpOn_.setSize(n, covered_ != nullptr);
    if (covered_ && cd.subDict("buildUp").found("patches"))
    {
        const dictionary& b = cd.subDict("buildUp");
        const wordRes sel(b.get<wordRes>("patches"));
        snowWallDetail::checkNotEmpty(b, sel, "buildUp");
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
    // the snow patches whose sticks are recorded: stickRecords, or none
    recordSticks_.setSize(n, false);
    stickLines_.setSize(n);
    if (cd.found("stickRecords"))
    {
        const wordRes sel(cd.get<wordRes>("stickRecords"));
        if (sel.empty())
        {
            snowWallDetail::fatalAt(cd, cd.findEntry("stickRecords", keyType::LITERAL))
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
    setupWallRegimes(cd);
    {
        const label sd = cd.lookupOrDefault<label>("randomSeed", 1234567);
        if (sd < 0)
        {
            snowWallDetail::fatalAt(cd, cd.findEntry("randomSeed", keyType::LITERAL))
                << "snowWallInteraction: randomSeed " << sd << " must be >= 0"
                << exit(FatalIOError);
        }
        seed_ = sd;
        drawMatters_ = covered_ != nullptr;
        forAll(slotModel_, si)
        {
            if (sww_probability_table(slotModel_[si], nullptr, nullptr)) drawMatters_ = true;
        }
    }
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
             && (groupType_[g] == 3 || (groupType_[g] == 0 && openPatch_[patchi]))
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
        // absent before issue 23: the counts by reason then start here
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


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::SnowWallInteraction<CloudType>::SnowWallInteraction
(
    const dictionary& dict,
    CloudType& cloud
)
:
    PatchInteractionModel<CloudType>(dict, cloud, typeName),
    patchData_(cloud.mesh(), checkedPatches(cloud.mesh(), this->coeffDict())),
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

    vector& U = p.U();

    // Bookkeeping: the cloud (KinematicParcel::hitPatch) has already counted
    // a hit on an open patch (neither wall nor constraint) as escaped. A
    // parcel removed here without a deposit is an escape; one kept, or
    // deposited, is not.
    const scalar mp = p.mass()*p.nParticle();
    const bool open = openPatch_[pp.index()];

    switch (groupType_[groupi])
    {
        case 0: // none: the cloud removes it on an open patch (counted)
        {
            if (open)
            {
                ++nReason_[(SWW_NCLASS + 1)*reportOfPatch_[pp.index()] + SWW_NCLASS];
            }
            return false;
        }
        case 1: // rebound, as localInteraction
        {
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
            return true;
        }
        case 2: // stick, as localInteraction
        {
            if (open) uncountEscape(mp);
            keepParticle = true;
            p.active(false);
            U = Zero;
            return true;
        }
        case 3: // escape
        {
            ++nReason_[(SWW_NCLASS + 1)*reportOfPatch_[pp.index()] + SWW_NCLASS];
            if (!open) this->addToEscapedParcels(mp);
            keepParticle = false;
            p.active(false);
            U = Zero;
            return true;
        }
        default:
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

    // counts by reason per reported patch and in total (issue 23)
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


// ************************************************************************* //
