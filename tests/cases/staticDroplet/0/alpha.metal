/*--------------------------------*- C++ -*----------------------------------*\
  ldnaFoam test case: static liquid cylinder (Laplace pressure)
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
    walls       { type zeroGradient; }
    frontAndBack { type empty; }
}

// ************************************************************************* //
