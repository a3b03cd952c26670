"""Python tooling for ldnaFoam."""
