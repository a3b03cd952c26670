/*--------------------------------*- C++ -*----------------------------------*\
  ldnaFoam test case: a Gaussian source moving over a solid (Eagar-Tsai)
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
internalField   uniform 1;

boundaryField
{
    inlet       { type fixedValue; value uniform 1; }
    outlet      { type zeroGradient; }
    symmetry    { type symmetryPlane; }
    farField    { type zeroGradient; }
    surface     { type zeroGradient; }
}

// ************************************************************************* //
