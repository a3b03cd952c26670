/*---------------------------------------------------------------------------*\
  ldnaFoam: laser-assisted double-wire deposition welding
  Licence: GPL-3.0-or-later, as OpenFOAM's, on which it is built (LICENSE)
-------------------------------------------------------------------------------
Application
    ldnaFoam

Group
    grpMultiphaseSolvers

Description
    Solver for laser-assisted double-wire deposition welding with a
    non-transferred arc (LDNA): two compressible, non-isothermal immiscible
    fluids, metal (solid and liquid steel) and shielding gas, with a VOF
    (volume of fluid) interface capturing approach, MULES with
    sub-cycling, surface tension, gravity and an adaptive time step, in the
    idiom of compressibleInterFoam.

    The energy equation conserves the total enthalpy including the latent
    heat of fusion (see metalGasMixture).  Every physical effect of the
    process (enthalpy-porosity, droplets, laser, Marangoni, evaporation,
    surface losses) enters through fvOptions listed by the case:
      - alpha.<metal> with density rho.<metal>: metal mass source [kg/m3/s]
        (continuity, phase fraction and pressure equations); the metal
        arrives at the local temperature, so a source alone neither heats
        nor cools
      - U: momentum source [N/m3]
      - T: heat source [W/m3]

    The flow is laminar (Newtonian melt, paper assumption); pressure work
    and viscous heating are neglected in the energy equation (low Mach).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "EulerDdtScheme.H"
#include "localEulerDdtScheme.H"
#include "gaussConvectionScheme.H"
#include "alpha/metalFractionLimiter.H"
#include "alpha/solidMetalFlux.H"
#include "balances/domainBalances.H"
#include "energy/boundedEnthalpyFlux.H"
#include "energy/energyControls.H"
#include "metal/metalSources.H"
#include "pU/fluxReconstruction.H"
#include "pU/upwindDensity.H"
#include "time/capillaryDeltaT.H"
#include "subCycle.H"
#include "metalGasMixture.H"
#include "pimpleControl.H"
#include "fvOptions.H"
#include "metalDrift.H"
#include "optionsImplementing.H"
#include "upwind.H"
#include "checkedInput.H"
#include "fieldIO.H"
#include "profiling.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Laser-assisted double-wire deposition welding:"
        " compressible VOF metal and shielding gas with melting and"
        " solidification."
    );

    #include "postProcess.H"

    #include "addCheckCaseOptions.H"
    #include "setRootCaseLists.H"
    #include "createTime.H"
    #include "createMesh.H"
    #include "createControl.H"
    #include "createTimeControls.H"
    #include "createFields.H"

    #include "readTimeControls.H"
    #include "CourantNo.H"
    #include "setInitialDeltaT.H"

    // * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

    balances.write(mixture, T, alpha1);

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        #include "readTimeControls.H"
        #include "time/checkControls.H"
        addProfiling(deltaT, "ldnaFoam.setDeltaT");
        #include "CourantNo.H"
        #include "alphaCourantNo.H"
        #include "time/adjustDeltaT.H"
        endProfiling(deltaT);

        ++runTime;

        Info<< "Time = " << runTime.timeName() << nl << endl;

        #include "energy/storeEnergy.H"

        // --- Pressure-velocity PIMPLE corrector loop
        while (pimple.loop())
        {
            // Each stage is timed when controlDict has profiling active
            addProfiling(alpha, "ldnaFoam.alpha");
            metal.collect(fvOptions, metalSourceDensity, alpha1);
            #include "alpha/metalFractionEqn.H"
            #include "metal/fillerEqn.H"
            endProfiling(alpha);

            addProfiling(momentum, "ldnaFoam.UEqn");
            #include "pU/UEqn.H"
            endProfiling(momentum);

            addProfiling(energy, "ldnaFoam.TEqn");
            #include "energy/TEqn.H"
            endProfiling(energy);

            // --- Pressure corrector loop
            addProfiling(pressure, "ldnaFoam.pEqn");
            #include "pU/pEqn.H"
            endProfiling(pressure);
        }

        addProfiling(insertion, "ldnaFoam.insertMetal");
        metal.endStep(metalSourceDensity, mixture.h1());
        #include "metal/insertMetal.H"
        endProfiling(insertion);
        balances.write(mixture, T, alpha1);
        #include "time/write.H"

        runTime.printExecutionTime(Info);
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
