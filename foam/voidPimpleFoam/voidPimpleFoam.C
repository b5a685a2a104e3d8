/*---------------------------------------------------------------------------*\
Application
    voidPimpleFoam

Description
    Transient solver for the volume-averaged incompressible flow of a Newtonian fluid through
    DEM particles (CFD-DEM, unresolved): void-fraction-weighted continuity and momentum,
    PIMPLE, laminar or with OpenFOAM's turbulence models. The particles (dem/), the void
    fraction, the exchange coefficient and the particle sources come from the C coupling layer
    (coupling/src/coupling.h) through the demCoupling adapter (foam/adapter).

    Equations (per unit volume of mixture, divided by rho_f; alpha = fluid volume fraction,
    U = interstitial fluid velocity, phi = interstitial face flux, p = KINEMATIC pressure
    p_real/rho_f including the hydrostatic part, g = gravity):

    continuity
        ddt(alpha) + div(alpha U) = 0
      solved as the pressure equation (CFDEM/DPMFoam style, alpha changes with the particles):
        laplacian(alpha_f c_f rAU_f, p) = ddt(alpha) + div(alpha_f phiHbyA)
      with c = 1 (model B) or alpha (model A).

    momentum (conservative)
        ddt(alpha U) + div(alpha phi, U)
      - div(alpha nu (grad(U) + dev2(T(grad(U)))))
      = - c grad(p)                         c = 1 (model B) or alpha (model A)
        + alpha g                           gravity as a body force on the fluid
        + Ksl/rho_f (Up - U)                drag, implicit: fvm::Sp(Ksl/rho_f, U) on the left,
                                            Ksl/rho_f Up as a source
        + fExplicit/rho_f                   other particle forces on the fluid
      DPMFoam and CFDEM subtract U [ddt(alpha) + div(alpha phi)] (the continuity residual of the
      lagged flux); that is a momentum source the pressure drop does not see, so it is not done.
      The explicit sources (Ksl Up + fExplicit)/rho_f and alpha g enter as face fluxes
      (phiForces, as DPMFoam's phicForces), so that pressure and body forces balance face by
      face and a fluid at rest stays at rest (with fixedFluxPressure on walls).

    faceMomentum (PIMPLE { faceMomentum true; }, the default; false gives the cell form):
      the momentum equation is solved at the faces for the flux, every term with face
      coefficients (as twoPhaseEulerFoam's faceMomentum; pEqnFace.H):
        (alpha_f phi - alpha_f^0 phi^0)/dt + interp(A) phi - flux(H) + Kf phi
          = flux((Ksl Up + fExplicit)/rho_f) + alpha_f g.S_f - c snGrad(p) |S_f|
      with A, H of the momentum matrix without the time derivative and the drag, c = 1
      (model B) or, model A, the gas's share of the face's pressure jump when the jump is
      split between the two half cells in proportion to their resistance (pressureSplit.H;
      the particles feel the rest, so that momentum is exchanged face by face), and
      Kf = alpha_f interpolate(Ksl/(rho_f alpha)), the resistance per unit superficial
      velocity interpolated; the cell velocity is rebuilt from the superficial fluxes,
      U = reconstruct(alpha_f phi)/alpha. Each face term is the interpolation of the cell
      term it stands for, so that summed over a column the pressure drop equals the force
      the particles give the fluid, its weight and its acceleration (momentumBalance.H
      writes that balance every step), and a packed cell next to free fluid keeps its drag
      (the bed's ends keep their pressure drop, the free fluid has no odd-even pattern).
      The cell form (faceMomentum false, DPMFoam's) has the time derivative and the drag
      in the cells and a momentum predictor; conservative as the face form (no U x continuity
      residual term, the explicit forces as rAU_f x face fluxes) it also balances momentum,
      but a packed cell next to free fluid gets about half its velocity (half a cell of
      pressure drop lost at each end of a packed bed).

    Since p keeps its hydrostatic part, the C side gets the full gradient [Pa/m]
    (rho_f fvc::grad(p); model A: rho_f times pressureSplit's cell gradient, the particles'
    share of each face's jump) and computes the particles' pressure-gradient (buoyancy) force
    from it. With alpha = 1 and Ksl = 0 the equations are pimpleFoam's (laminar).

    One fluid time step (deltaT of system/controlDict, fixed: adjustTimeStep is refused):
      1. coupling: couplingInterval DEM steps with the drag of the current U and grad(p),
         then alpha, Ksl, Up, fExplicit of the new particle state (alpha's old value is kept
         for ddt(alpha));
      2. fluid: the PIMPLE loop;
      3. the momentum balance of the fluid (postProcessing/momentumBalance.dat);
         write times: alpha, U, p, phi, Ksl, Up, fExplicit and particleSource
         (= Ksl (Up - U) + fExplicit [N/m^3], the particles' force density on the fluid)
         as OpenFOAM fields; particles to <case>/particles.h5 + particles.xdmf (also at the
         start time).

    Input
      constant/transportProperties   transportModel Newtonian; nu [0 2 -1 0 0 0 0] 1e-6;
                                     rho [1 -3 0 0 0 0 0] 1000;   (rho_f for the coupling)
      constant/g                     optional; otherwise gravity of constant/demProperties
                                     (if both are given they must agree)
      constant/demProperties         the DEM (as for demRun)         } read by the C side
      constant/couplingProperties    couplingInterval, void fraction } (errors name file
                                     model, drag law, model A/B, ... } and key)
      0/U, 0/p                       p: fixedFluxPressure on walls when gravity is on
      system/fvSchemes               also div(alphaPhi,U), laplacian(alphaNu,U),
                                     div(((alpha*nuEff)*dev2(T(grad(U))))) (the name DPMFoam uses)
      system/fvSolution              PIMPLE { nOuterCorrectors; nCorrectors;
                                     nNonOrthogonalCorrectors; pRefCell; pRefValue; }

      constant/turbulenceProperties  optional: OpenFOAM's incompressible turbulence models,
                                     phase-weighted as DPMFoam's (phaseTurbulence.H), with
                                     their fields in 0/ (k, epsilon or omega, nut); without
                                     it the gas is laminar
      constant/drivingGradient       optional: a periodic pipe's driving gradient, holding the
                                     mean superficial or interstitial velocity (drivingGradient.H)

    Serial, or parallel after decomposePar: mpirun -np N voidPimpleFoam -parallel (each rank's
    cells go to the C side, the DEM is decomposed over the same ranks, and each particle's
    copies go to the ranks whose cells it reaches; coupling/src/proxies.h). The tutorials'
    Allrun -np N decompose, run and reconstruct.

    The equations of models A and B, numbered, with their sources and choices:
    docs/models/forces_modelA_B.md (the exchange: docs/models/exchange_implicit_explicit.md).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "singlePhaseTransportModel.H"
#include "pimpleControl.H"
#include "fvOptions.H"
#include "uniformDimensionedFields.H"
#include "IFstream.H"
#include "clockTime.H"
#include "OFstream.H"
#include <fstream>
#include <cstdlib>
#include "wallFvPatch.H"
#include "fixedFluxPressureFvPatchScalarField.H"

#include "phaseTurbulence.H"
#include "demCoupling.H"
#include "fluxReconstruction.H"
#include "heldTraps.H"
#include "drivingGradient.H"
#include "pressureSplit.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Transient solver for the volume-averaged incompressible flow of a"
        " Newtonian fluid with DEM particles (void fraction, implicit drag),"
        " coupled to the project's C DEM through libcoupling."
    );

    #include "postProcess.H"

    #include "addCheckCaseOptions.H"
    #include "setRootCaseLists.H"

    const clockTime wallClock;     // the run's wall time, for the time split at the end

    #include "createTime.H"
    #include "createMesh.H"
    #include "createControl.H"
    #include "createFields.H"
    #include "initContinuityErrs.H"

    // U from the superficial face fluxes (the face form), with the mesh's tensor inverted once
    const fluxReconstruction reconstruction(mesh);

    // --- the coupling session: copies the mesh, reads demProperties and couplingProperties
    demCoupling coupling(mesh, rhoFluid.value(), nuFluid, runTime.deltaTValue(), runTime.value());

    const bool modelA = coupling.modelA();
    // A periodic pipe's driving gradient (constant/drivingGradient; none without it)
    drivingGradient driving(mesh, rhoFluid.value(), faceMomentum);
    // c of the pressure term at the faces: model A the gas's share of the face's pressure jump
    // (pressureSplit.H; alpha_f until the coupling's first fields), model B 1
    surfaceScalarField pCoeff_f("pCoeff_f", alphaf);
    const pressureSplit pressureShares(mesh);
    // the gas's share of a periodic pipe's driving gradient at the faces: alpha_f (model A), 1 (B).
    // The drive is uniform, so it is shared as the cells' volumes are, not by resistance
    surfaceScalarField driveCoeff_f("driveCoeff_f", alphaf);
    // one step's inertia rho_f/dt [kg/(m^3 s)], beside the drag in pressureSplit's weights
    const dimensionedScalar stepInertia("stepInertia", Ksl.dimensions(), rhoFluid.value()/runTime.deltaTValue());

    // The initial void fraction: a continued run's as written at its start time, else the C
    // side's, if it has one before the first step
    const bool haveInitialAlpha =
        (coupling.restarted() && alpha.headerOk()) || coupling.initialAlpha(alpha);
    if (!haveInitialAlpha)
    {
        Info<< "The coupling layer gives no initial void fraction: alpha starts at 1 and"
            << " the first step takes ddt(alpha) = 0" << nl << endl;
    }
    alphaf = fvc::interpolate(alpha);
    alphaPhi = alphaf*phi;

    // A run from t = 0 begins from its initial conditions; from a later time it continues
    // (the fields of that time, the particles of their snapshot at that time)
    const bool restarted = coupling.restarted();
    #include "initialFlow.H"

    // The fluid's momentum int(alpha U) dV at the last step, and the balance file
    // (momentumBalance.H)
    vector momentumOld(gSum(alpha.primitiveField()*U.primitiveField()*mesh.V().field()));
    autoPtr<OFstream> momentumFile, drivingFile, wallShearFile;

    // The particles' initial state opens the HDF5/XDMF series (a continued run has it already)
    if (!restarted)
    {
        coupling.write(runTime.value());
    }

    #include "CourantNo.H"

    Info<< "\nStarting time loop\n" << endl;

    clockTime clock, stageClock;
    scalar fluidTime = 0, momentumTime = 0, pressureTime = 0, turbulenceTime = 0;
    const scalar startTime = runTime.value();
    scalar nextProgress = 30;
    label stepi = 0;

    while (runTime.run())
    {
        #include "CourantNo.H"

        ++runTime;
        ++stepi;

        Info<< "Time = " << runTime.timeName() << nl << endl;

        // --- 1. DEM steps and coupling: alpha, Ksl, Up, fExplicit at the new time
        clock.timeIncrement();

        if (driving.active())
        {
            coupling.setDrive(driving.drive());   // the particles feel the gas's driving gradient
        }
        // model A: the particles' share of each face's pressure jump (pressureSplit.H)
        coupling.evolve
        (
            U,
            modelA ? pressureShares.cellGradient(p, alpha, Ksl, stepInertia)() : fvc::grad(p)()
        );
        coupling.update(alpha, Ksl, Up, fExplicit);
        if (stepi == 1 && !haveInitialAlpha)
        {
            alpha.oldTime() == alpha;
        }
        alphaf0 = fvc::interpolate(alpha.oldTime());
        alphaf = fvc::interpolate(alpha);
        alphaPhi = alphaf*phi;

        if (modelA)
        {
            pressureShares.faceCoefficient(pCoeff_f, alpha, Ksl, stepInertia);
            driveCoeff_f = alphaf;
        }
        else
        {
            pCoeff_f = dimensionedScalar("one", dimless, 1.0);
            driveCoeff_f = pCoeff_f;
        }

        clock.timeIncrement();     // (the coupling's time is measured by the C side)

        // --- 2. Pressure-velocity PIMPLE corrector loop (each part timed for the end-of-run split)
        while (pimple.loop())
        {
            stageClock.timeIncrement();
            #include "UEqn.H"
            momentumTime += stageClock.timeIncrement();

            // --- Pressure corrector loop
            while (pimple.correct())
            {
                if (faceMomentum)
                {
                    #include "pEqnFace.H"
                }
                else
                {
                    #include "pEqn.H"
                }
            }
            pressureTime += stageClock.timeIncrement();

            if (pimple.turbCorr())
            {
                laminarTransport.correct();
                if (turbulence.valid())
                {
                    turbulence->correct();
                }
            }
            turbulenceTime += stageClock.timeIncrement();
        }

        particleSource = Ksl*(Up - U) + fExplicit;
        if (driving.active())
        {
            Info<< "Driving gradient " << driving.gradient() << " Pa/m: mean superficial velocity "
                << driving.superficialVelocity() << " m/s, interstitial " << driving.interstitialVelocity()
                << " m/s (" << driving.held() << " held)" << nl;
        }

        fluidTime += clock.timeIncrement();

        #include "momentumBalance.H"

        // --- 3. output
        if (runTime.writeTime())
        {
            coupling.write(runTime.value());
        }
        runTime.write();
        driving.write();

        {
            vector vp, xp;
            coupling.particleMeans(vp, xp);
            scalar demT, cplT, lifeT;
            coupling.timings(demT, cplT, lifeT);
            Info<< "Particles: " << coupling.nParticles()
                << ", mean velocity " << vp << " m/s, mean position " << xp << " m" << nl
                << "alpha: min " << gMin(alpha.primitiveField())
                << ", mean " << alpha.weightedAverage(mesh.V()).value()
                << "; particle force on the fluid: " << fvc::domainIntegrate(particleSource).value()
                << " N" << nl
                << "Wall time so far: DEM " << demT << " s, coupling " << cplT
                << " s, fluid " << fluidTime << " s" << nl;
        }

        runTime.printExecutionTime(Info);

        // progress of a long run, every 30 s of wall time: simulated time, share, time to go
        if (wallClock.elapsedTime() > nextProgress)
        {
            const scalar done = (runTime.value() - startTime)/max(runTime.endTime().value() - startTime, SMALL);
            const scalar spent = wallClock.elapsedTime();
            Info<< "Progress: t = " << runTime.timeName() << " s of " << runTime.endTime().value()
                << " s (" << label(100*done) << " %), " << label(spent) << " s wall so far, about "
                << label(done > 0 ? spent*(1 - done)/done : 0) << " s to go" << nl << endl;
            nextProgress = spent + 30;
        }
    }

    {
        scalar demT, cplT, lifeT;
        coupling.timings(demT, cplT, lifeT);
        const scalar total = max(wallClock.elapsedTime(), SMALL);
        Info<< nl << "Time split over " << stepi << " fluid steps ("
            << stepi*coupling.interval() << " DEM steps):" << nl
            << "    DEM       " << demT << " s (" << 100*demT/total << " %)" << nl
            << "      of which insertion/removal " << lifeT << " s (" << 100*lifeT/total << " %)" << nl
            << "    coupling  " << cplT << " s (" << 100*cplT/total << " %)" << nl
            << "    fluid     " << fluidTime << " s (" << 100*fluidTime/total << " %)" << nl
            << "      momentum predictor (UEqn) " << momentumTime << " s (" << 100*momentumTime/total << " %)" << nl
            << "      pressure correctors (pEqn" << (faceMomentum ? "Face" : "") << ") " << pressureTime
            << " s (" << 100*pressureTime/total << " %)" << nl
            << "      turbulence and transport  " << turbulenceTime << " s (" << 100*turbulenceTime/total << " %)" << nl
            << "      the rest (alpha at the faces, the source, driving gradient) "
            << fluidTime - momentumTime - pressureTime - turbulenceTime << " s" << nl
            << "    total     " << total << " s (wall, including start-up and output)" << nl
            << endl;
        coupling.reportTimings();
        Info<< endl;
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
