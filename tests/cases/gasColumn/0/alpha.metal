/*--------------------------------*- C++ -*----------------------------------*\
  ldnaFoam test case: gas enclosed in a column of liquid 316L
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
    walls   { type zeroGradient; }
    sides   { type empty; }
}

// ************************************************************************* //
