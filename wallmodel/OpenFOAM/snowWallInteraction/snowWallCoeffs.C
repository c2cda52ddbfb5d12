/*---------------------------------------------------------------------------*\
  SnowWall: wallmodel/OpenFOAM/snowWallInteraction
-------------------------------------------------------------------------------
Description
    The reading and checking of snowWallInteractionCoeffs (see
    snowWallCoeffs.H): compiled once, not per cloud type.

\*---------------------------------------------------------------------------*/

#include "snowWallCoeffs.H"
#include "Time.H"
#include "volFields.H"
#include "Switch.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "patchInteractionData.H"
#include "emptyPolyPatch.H"
#include "processorPolyPatch.H"
#include "wallPolyPatch.H"
#include <fstream>
#include <initializer_list>
#include <cctype>
#include <cmath>
#include <cstdlib>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{
namespace snowWallCoeffs
{


//- The files a dictionary file reads: itself and, recursively (depth 4),
//  the files its #include / #includeIfPresent lines name (relative to the
//  including file's folder, environment variables expanded)
static void dictFiles(const fileName& f, DynamicList<fileName>& out, int depth)
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
static bool lineHasKey(const List<std::string>& lines, label n, const std::string& key)
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
static bool lineHasValue(const List<std::string>& lines, const entry& e)
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
fileName dictFile(const dictionary& d)
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
static fileName blockFile(const dictionary& d, const std::string& key, label line)
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
    // keys at the same lines, so the keys alone could name the file of a
    // wallRegimes or buildUp entry for an error in the main regime
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
OSstream& fatalAt(const dictionary& d, const entry* e)
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
//  mean two things (a repeated key, a repeated regime block). The file is
//  read again on its own with OpenFOAM's inputMode error; its FatalIOError
//  is caught and given again with the file, the line and the key.
static void checkNoDuplicates(const fileName& f)
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
scalar checkedNumber
(
    const dictionary& d,
    const word& key,
    scalar lo,
    scalar hi,
    const char* unit,
    const char* what,
    bool openLo
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
static void checkKeys
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
void checkNotEmpty(const dictionary& d, const wordRes& sel, const std::string& what)
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
static void checkCoeffKeys(const dictionary& cd)
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

//- Whether the shear gate's field will be there at the first impact: it is
//  registered now, or it can be read from the start time's folder, or a
//  function object of system/controlDict makes it (a wallShearStress entry
//  makes "wallShearStress"; any entry whose 'result' names it is taken at
//  its word). Checked at set-up, before the function objects start and
//  write anything: a case that cannot run leaves no postProcessing/ behind.
static bool shearFieldProvided(const fvMesh& mesh, const word& name)
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

//- The rebound of a bounce: the kernel's tables of the regime file when it
//  has them (auto), required (table), or the classic Thornton / constant e_n
//  with reboundTangential (classic)
static void applyRebound
(
    const string& context,
    sww_model* m,
    const dictionary& cd
)
{
    const word rb(cd.lookupOrDefault<word>("rebound", "auto"));
    const int code =
        rb == "auto" ? SWW_REBOUND_AUTO
      : rb == "table" ? SWW_REBOUND_TABLE
      : rb == "classic" ? SWW_REBOUND_CLASSIC
      : -1;
    if (code < 0)
    {
        fatalAt(cd, cd.findEntry("rebound", keyType::LITERAL))
            << "snowWallInteraction: rebound '" << rb
            << "' is not auto, table or classic" << exit(FatalIOError);
    }
    check(context, m, sww_set_rebound_model(m, code), cd, cd.findEntry("rebound", keyType::LITERAL));
}

//- The tangential gate (tangentialGate) of coefficients cd on model m:
//  a constant v_t limit, or the regime's oblique or stick-probability table
static void applyTangentialGate
(
    const string& context,
    sww_model* m,
    const dictionary& cd
)
{
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
                    context,
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
                // wall=lattice --vt 0,...)
                check(context, m, sww_set_tangential_regime(m), g);
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
                        fatalAt(g, te)
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
                        context,
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
}

//- The shear gate (shearGate) of coefficients cd on model m: when active,
//  shearOn, the field name tauName (checked to be provided at the first
//  impact) and rhoAir (-1 when not given)
static void applyShearGate
(
    const string& context,
    sww_model* m,
    const dictionary& cd,
    const fvMesh& mesh,
    bool& shearOn,
    word& tauName,
    scalar& rhoAir
)
{
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
                    context,
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
                    context,
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
            shearOn = true;
            tauName = g.lookupOrDefault<word>("field", "wallShearStress");
            if
            (
               !shearFieldProvided
                (
                    mesh, tauName
                )
            )
            {
                FatalIOErrorInFunction(g)
                    << "snowWallInteraction: shearGate: the field '"
                    << tauName << "' is not registered, not in the "
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
            rhoAir =
                g.found("rhoAir", keyType::LITERAL)
              ? checkedNumber
                (
                    g, "rhoAir", 1e-6, 1e4, "kg/m3",
                    "the air density that turns a kinematic wall shear stress into Pa"
                )
              : -1.0;
        }
    }
}

} // End namespace snowWallCoeffs
} // End namespace Foam


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

const Foam::dictionary& Foam::snowWallCoeffs::checkedPatches
(
    const polyMesh& mesh,
    const dictionary& coeffs
)
{
    // patchInteractionDataList (read next) only warns about a pattern that
    // matches nothing and blames "local patch interaction" for a patch
    // without an entry: both are errors here, naming the file
    // the first thing read of the coefficients: every key known
    checkCoeffKeys(coeffs);
    const polyBoundaryMesh& bm = mesh.boundaryMesh();
    const List<patchInteractionData> items(coeffs.lookup("patches"));
    if (items.empty())
    {
        fatalAt(coeffs, coeffs.findEntry("patches", keyType::LITERAL))
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
                << it.patchName() << " of " << dictFile(coeffs)
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
                << t << ") of " << dictFile(coeffs)
                << ": parcels reaching it "
                << (t == "escape" ? "leave the cloud" : "pass through")
                << " and no snow settles there. Name the patch in patches "
                << "(...) before that entry if it is a wall the snow meets"
                << endl;
        }
    }
    return coeffs;
}



void Foam::snowWallCoeffs::check
(
    const string& context,
    const sww_model* m,
    int rc,
    const dictionary& dict,
    const entry* e
)
{
    if (rc != SWW_OK)
    {
        fatalAt(dict, e)
            << "snowWallInteraction: " << context.c_str() << sww_errmsg(m)
            << exit(FatalIOError);
    }
}


void Foam::snowWallCoeffs::readRegime
(
    const string& context,
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
            fatalAt(regimeDict, &e)
                << "snowWallInteraction: regime key '" << e.keyword()
                << "': cannot read value " << is << exit(FatalIOError);
        }
        check(context, m, rc, regimeDict, &e);
    }
    // the C core's message starts with the origin, the dictionary's keyword;
    // check() adds the file and lines (read only on an error)
    const std::string origin(regimeDict.dictName());
    check(context, m, sww_regime_commit(m, origin.c_str()), regimeDict);
    // an #included regime file: no repeated key or block (an inline regime
    // block follows OpenFOAM's convention of its dictionary: merged)
    const fileName f(blockFile(regimeDict, std::string(), -1));
    if (f != dictFile(regimeDict))
    {
        checkNoDuplicates(f);
    }
}



void Foam::snowWallCoeffs::applyGates
(
    const string& context,
    sww_model* m,
    const dictionary& cd,
    const fvMesh& mesh,
    bool& shearOn,
    word& tauName,
    scalar& rhoAir
)
{
    check
    (
        context,
        m,
        sww_set_rebound_tangential
        (
            m, cd.lookupOrDefault<scalar>("reboundTangential", 1.0)
        ),
        cd
    );

    applyRebound(context, m, cd);
    applyTangentialGate(context, m, cd);
    applyShearGate(context, m, cd, mesh, shearOn, tauName, rhoAir);
}



bool Foam::snowWallCoeffs::removeStuckParcels(const dictionary& cd)
{
    const word stuck(cd.lookupOrDefault<word>("stuckParcels", "remove"));
    if (stuck == "remove")
    {
        return true;
    }
    if (stuck != "keep")
    {
        FatalIOErrorInFunction(cd)
            << "snowWallInteraction: stuckParcels '" << stuck
            << "' is not remove or keep" << exit(FatalIOError);
    }
    return false;
}


Foam::scalar Foam::snowWallCoeffs::coverMass
(
    const dictionary& b,
    const scalar rho,
    scalar& dCover
)
{
    // every number checked before it is used (a non-positive one made a NaN
    // whose comparison OpenFOAM traps as SIGFPE)
    scalar mass = -1;
    dCover = -1;
    const bool hasMass = b.found("coverMass", keyType::LITERAL);
    const bool hasD = b.found("coverDiameter", keyType::LITERAL);
    if (hasMass && hasD)
    {
        fatalAt(b, b.findEntry("coverDiameter", keyType::LITERAL))
            << "snowWallInteraction: buildUp: give coverDiameter or "
            << "coverMass, not both (coverMass would be used, "
            << "coverDiameter ignored)" << exit(FatalIOError);
    }
    if (hasMass)
    {
        mass = checkedNumber
        (
            b, "coverMass", 0, coverMassMax, "kg/m2",
            "the covering mass per area of a face", true
        );
    }
    else if (hasD)
    {
        dCover = checkedNumber
        (
            b, "coverDiameter", 0, coverDMax, "m",
            "the mean particle diameter: one monolayer covers a face", true
        );
        mass = sww_monolayer_mass(rho, dCover);
        if (!std::isfinite(mass) || mass <= 0 || mass > coverMassMax)
        {
            fatalAt(b, b.findEntry("coverDiameter", keyType::LITERAL))
                << "snowWallInteraction: buildUp: coverDiameter " << dCover
                << " m with the cloud's particle density rho0 " << rho
                << " kg/m3 (constantProperties) gives a covering mass "
                << mass << " kg/m2 outside the accepted range (0, "
                << coverMassMax << "] kg/m2: check rho0, "
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
    return mass;
}


Foam::label Foam::snowWallCoeffs::randomSeed(const dictionary& cd)
{
    const label sd = cd.lookupOrDefault<label>("randomSeed", 1234567);
    if (sd < 0)
    {
        fatalAt(cd, cd.findEntry("randomSeed", keyType::LITERAL))
            << "snowWallInteraction: randomSeed " << sd << " must be >= 0"
            << exit(FatalIOError);
    }
    return sd;
}


// ************************************************************************* //
