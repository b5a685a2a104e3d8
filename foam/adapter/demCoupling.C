/*---------------------------------------------------------------------------*\
    demCoupling: the OpenFOAM side of the C coupling layer (see demCoupling.H)
\*---------------------------------------------------------------------------*/

#include "demCoupling.H"
#include "fvc.H"
#include "Pstream.H"
#include "cyclicPolyPatch.H"
#include "processorCyclicPolyPatch.H"

#include <cstdlib>
#include <type_traits>
#include <unistd.h>

#include "coupling.h"       // C API (extern "C"), coupling/src
#include "error.h"          // the C libraries' fatal handler and logger, dem/src
#include "dem_mpi_world.h"  // the C libraries' messages over MPI (dem/mpi), for -parallel

// The arrays go across without conversion: label must be a C int and a vector three packed doubles
static_assert(sizeof(Foam::label) == sizeof(int), "label must be int32 (WM_LABEL_SIZE=32)");
static_assert(std::is_same<Foam::scalar, double>::value, "scalar must be double (WM_PRECISION_OPTION=DP)");
static_assert(sizeof(Foam::vector) == 3*sizeof(double), "vector must be three packed doubles");
static_assert(sizeof(Foam::point) == 3*sizeof(double), "point must be three packed doubles");

namespace
{
    // A vectorField as the C side's double (*)[3]
    inline const double (*c3(const Foam::vectorField& f))[3]
    {
        return reinterpret_cast<const double (*)[3]>(f.cdata());
    }

    // An error in the C libraries (a dictionary's with "file:line: error: key ...") stops the
    // run as OpenFOAM's own errors do. The C frames it is called from cannot be unwound, so it
    // stops the program even where FatalError was set to throw.
    void raiseFatalError(const char* where, const char* message)
    {
        // -parallel: an error every rank meets (the input) is said once, by the master, whose
        // abort ends the others during their wait; an error of one rank alone after it
        if (Foam::Pstream::parRun() && !Foam::Pstream::master())
        {
            sleep(2);
        }
        Foam::FatalError.throwExceptions(false);
        Foam::OSstream& os = FatalErrorInFunction;
        if (where)
        {
            os << where << ": ";
        }
        os << "error: " << message << Foam::exit(Foam::FatalError);
    }

    // The C libraries' info and warning lines, through OpenFOAM's streams (master only)
    void writeLog(dem_log_level level, const char* message)
    {
        if (level == DEM_LOG_WARNING)
        {
            Foam::Warning << message << Foam::endl;
        }
        else
        {
            Foam::Info << message << Foam::endl;
        }
    }

    // The hooks set before this adapter's, put back by the destructor
    dem_fatal_handler previousFatalHandler = nullptr;
    dem_logger previousLogger = nullptr;
}


// * * * * * * * * * * * * * * Static Member Functions  * * * * * * * * * * * * //

bool Foam::demCoupling::demGravity(const fileName& caseDir, vector& g)
{
    const dem_fatal_handler fatal = dem_set_fatal_handler(raiseFatalError);
    const dem_logger logger = dem_set_logger(writeLog);
    double cg[3];
    const bool found = coupling_case_gravity(caseDir.c_str(), cg);
    dem_set_fatal_handler(fatal);
    dem_set_logger(logger);
    g = vector(cg[0], cg[1], cg[2]);
    return found;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::demCoupling::demCoupling
(
    const fvMesh& mesh,
    scalar rho,
    scalar nu,
    scalar deltaT,
    scalar startTime
)
:
    mesh_(mesh),
    rho_(rho),
    session_(nullptr),
    cmesh_(nullptr),
    modelA_(false),
    interval_(0),
    adapterTime_(0),
    clock_()
{
    previousFatalHandler = dem_set_fatal_handler(raiseFatalError);
    previousLogger = dem_set_logger(writeLog);

    // -parallel: this rank's cells go to the C side, the DEM is decomposed over the same ranks
    // and the particles' copies go to the ranks whose cells they reach (coupling/src/proxies.h)
    if (Pstream::parRun())
    {
        dem_mpi_use_world();
    }

    // --- the mesh arrays, as OpenFOAM orders them (internal faces first)
    const pointField& pts = mesh.points();
    const faceList& faces = mesh.faces();
    const labelList& own = mesh.faceOwner();
    const labelList& nei = mesh.faceNeighbour();
    const label nFaces = faces.size();

    // faces as CSR
    List<int> faceStart(nFaces + 1);
    faceStart[0] = 0;
    forAll(faces, facei)
    {
        faceStart[facei + 1] = faceStart[facei] + faces[facei].size();
    }
    List<int> facePoints(faceStart[nFaces]);
    forAll(faces, facei)
    {
        const face& f = faces[facei];
        int k = faceStart[facei];
        forAll(f, i)
        {
            facePoints[k++] = f[i];
        }
    }

    const vectorField& C = mesh.C().primitiveField();
    const scalarField& V = mesh.V().field();

    // The session takes the mesh over (and frees its arrays); the struct is made with C's
    // allocator and kept until the session is freed.
    cmesh_ = static_cast<cpl_mesh*>(std::calloc(1, sizeof(cpl_mesh)));
    if (!cmesh_)
    {
        FatalErrorInFunction << "out of memory" << exit(FatalError);
    }
    cpl_mesh* m = cmesh_;

    cpl_mesh_init
    (
        m,
        pts.size(), c3(pts),
        nFaces, faceStart.cdata(), facePoints.cdata(),
        nei.size(), own.cdata(), nei.cdata(),
        mesh.nCells(), c3(C), V.cdata()
    );

    Info<< "demCoupling: mesh copied to the coupling layer: " << pts.size() << " points, "
        << nFaces << " faces (" << nei.size() << " internal), " << mesh.nCells()
        << " cells" << (Pstream::parRun() ? " on the master; each rank copies its own" : "") << nl;

    // Cyclic patches: OpenFOAM pairs face i of a cyclic patch with face i of its neighbour
    // patch; the C side takes the pairs (a translation along one axis, checked there) and sees
    // across them as across interior faces.
    // -parallel: a cyclic pair whose sides sit on two ranks (decomposePar made a
    // processorCyclic patch of it): the C side sees cyclic pairs within a rank only
    forAll(mesh.boundaryMesh(), patchi)
    {
        const polyPatch& pp = mesh.boundaryMesh()[patchi];
        if (isA<processorCyclicPolyPatch>(pp))
        {
            FatalErrorInFunction
                << "the decomposition cuts across a cyclic direction (processor patch " << pp.name()
                << "): each rank must hold both sides of every cyclic pair; in system/decomposeParDict"
                << " cut along the other directions only (simple or hierarchical n = 1 along the"
                << " periodic axis)" << exit(FatalError);
        }
    }
    forAll(mesh.boundaryMesh(), patchi)
    {
        const polyPatch& pp = mesh.boundaryMesh()[patchi];
        if (!isA<cyclicPolyPatch>(pp)) continue;
        const cyclicPolyPatch& cpp = refCast<const cyclicPolyPatch>(pp);
        if (!cpp.owner()) continue;
        if (!cpp.parallel())
        {
            FatalErrorInFunction
                << "cyclic patch " << cpp.name() << " is rotational: only translational cyclic patches "
                << "(a periodic box side) are supported" << exit(FatalError);
        }
        const cyclicPolyPatch& nbr = cpp.neighbPatch();
        List<int> a(cpp.size()), b(cpp.size());
        forAll(cpp, i)
        {
            a[i] = cpp.start() + i;
            b[i] = nbr.start() + i;
        }
        cpl_mesh_set_cyclic(m, cpp.size(), a.cdata(), b.cdata());
        Info<< "demCoupling: cyclic patches " << cpp.name() << " and " << nbr.name() << ": "
            << cpp.size() << " face pairs" << nl;
    }

    // the case itself (not processorN): demProperties, particles.h5, postProcessing
    const fileName caseDir(mesh.time().globalPath());
    session_ = coupling_create(caseDir.c_str(), m, rho, nu, deltaT, startTime);

    modelA_ = (coupling_model_type(session_) == CPL_MODEL_A);
    interval_ = coupling_interval(session_);

    Info<< "demCoupling: " << nParticles() << " particles, model " << modelName()
        << ", couplingInterval " << interval_ << " DEM steps per fluid step of "
        << deltaT << " s" << nl << endl;
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::demCoupling::~demCoupling()
{
    if (session_)
    {
        coupling_free(session_);
    }
    std::free(cmesh_);
    if (Pstream::parRun())
    {
        dem_mpi_release();
    }
    dem_set_fatal_handler(previousFatalHandler);
    dem_set_logger(previousLogger);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::demCoupling::restarted() const
{
    return coupling_restarted(session_);
}


Foam::label Foam::demCoupling::nParticles() const
{
    return coupling_particle_count(session_);
}


void Foam::demCoupling::evolve(const volVectorField& U, const volVectorField& gradp)
{
    clock_.timeIncrement();

    // Pressure gradient in Pa/m: OpenFOAM's p is kinematic (p/rho_f)
    const vectorField gradP(rho_*gradp.primitiveField());

    adapterTime_ += clock_.timeIncrement();

    coupling_evolve(session_, c3(U.primitiveField()), c3(gradP));

    clock_.timeIncrement();
}


void Foam::demCoupling::setDrive(const vector& drive)
{
    coupling_set_drive(session_, drive.cdata());
}


void Foam::demCoupling::update
(
    volScalarField& alpha,
    volScalarField& Ksl,
    volVectorField& Up,
    volVectorField& fExplicit
) const
{
    clock_.timeIncrement();

    const label n = mesh_.nCells();

    const double* a = coupling_alpha(session_);
    const double* k = coupling_ksl(session_);
    const double (*up)[3] = coupling_particle_velocity(session_);
    const double (*f)[3] = coupling_explicit_source(session_);

    if (!a || !k || !up || !f)
    {
        FatalErrorInFunction
            << "the coupling layer returned no "
            << (!a ? "alpha" : !k ? "Ksl" : !up ? "particle velocity" : "explicit source")
            << " field" << exit(FatalError);
    }

    scalarField& alphaI = alpha.primitiveFieldRef();
    scalarField& KslI = Ksl.primitiveFieldRef();
    vectorField& UpI = Up.primitiveFieldRef();
    vectorField& fI = fExplicit.primitiveFieldRef();

    for (label i = 0; i < n; ++i)
    {
        alphaI[i] = a[i];
        KslI[i] = k[i];
        UpI[i] = vector(up[i][0], up[i][1], up[i][2]);
        fI[i] = vector(f[i][0], f[i][1], f[i][2]);
    }

    alpha.correctBoundaryConditions();
    Ksl.correctBoundaryConditions();
    Up.correctBoundaryConditions();
    fExplicit.correctBoundaryConditions();

    adapterTime_ += clock_.timeIncrement();
}


bool Foam::demCoupling::initialAlpha(volScalarField& alpha) const
{
    const double* a = coupling_alpha(session_);
    if (!a)
    {
        return false;
    }
    const label n = mesh_.nCells();
    for (label i = 0; i < n; ++i)
    {
        if (!(a[i] > 0))
        {
            return false;
        }
    }
    scalarField& alphaI = alpha.primitiveFieldRef();
    for (label i = 0; i < n; ++i)
    {
        alphaI[i] = a[i];
    }
    alpha.correctBoundaryConditions();
    return true;
}


void Foam::demCoupling::write(scalar time)
{
    coupling_write(session_, time);
}


void Foam::demCoupling::particleMeans(vector& v, vector& x) const
{
    double vv[3], xx[3];
    coupling_particle_means(session_, vv, xx);
    v = vector(vv[0], vv[1], vv[2]);
    x = vector(xx[0], xx[1], xx[2]);
}


void Foam::demCoupling::particleForces(vector& fluid, vector& walls) const
{
    coupling_particle_forces(session_, fluid.data(), walls.data());
}


void Foam::demCoupling::timings(scalar& demTime, scalar& couplingTime, scalar& lifecycleTime) const
{
    double dem = 0, cpl = 0, life = 0;
    coupling_timings(session_, &dem, &cpl, &life);
    demTime = dem;
    couplingTime = cpl + adapterTime_;
    lifecycleTime = life;
}


void Foam::demCoupling::reportTimings()
{
    Info<< "Adapter time (fields copied between OpenFOAM and the C side): " << adapterTime_ << " s" << endl;
    coupling_report_timings(session_);
}


// ************************************************************************* //
