"""Command-line entry point ``ldna``."""
def main() -> int:
    return 0
