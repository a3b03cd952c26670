/*--------------------------------*- C++ -*----------------------------------*\
  ldnaFoam case template: LDNA moving-frame scene
\*---------------------------------------------------------------------------*/
FoamFile
{
    version     2.0;
    format      ascii;
    class       volScalarField;
    location    "0";
    object      alpha.metal;
}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

dimensions      [0 0 0 0 0 0 0];

internalField   uniform 0;      // set by setFields: 1 in the substrate

boundaryField
{
    substrateInlet
    {
        type            fixedValue;
        value           uniform 1;
    }
    substrateOutlet
    {
        type            zeroGradient;
    }
    substrateWalls
    {
        type            zeroGradient;
    }
    atmosphere
    {
        // Gas flows in, anything flows out (the bead leaves at x = length)
        type            inletOutlet;
        inletValue      uniform 0;
        value           uniform 0;
    }
}

// ************************************************************************* //
