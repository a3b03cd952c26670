/*--------------------------------*- C++ -*----------------------------------*\
  ldnaFoam test case: Marangoni flow in a thin liquid layer
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
internalField   uniform 0;
boundaryField
{
    hot         { type zeroGradient; }
    cold        { type zeroGradient; }
    walls       { type zeroGradient; }
    frontAndBack { type empty; }
}

// ************************************************************************* //
