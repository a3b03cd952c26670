"""Developer tools of the ldna package: what the project measures about
itself (``ldna bench``, ``bench-laser``, ``scaling``, ``accuracy``,
``bead-report``), apart from the user's commands; the ``ldna`` entry lists
both."""
