/*--------------------------------*- C++ -*----------------------------------*\
  ldnaFoam test case: a bar of filler on substrate metal, heated from above
\*---------------------------------------------------------------------------*/
FoamFile
{
    version     2.0;
    format      ascii;
    class       volScalarField;
    object      alpha.metal;
}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

dimensions      [0 0 0 0 0 0 0];
internalField   uniform 1;
boundaryField
{
    bottom { type zeroGradient; }
    top    { type zeroGradient; }
    sides  { type empty; }
}

// ************************************************************************* //
