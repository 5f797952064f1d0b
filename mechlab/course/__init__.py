"""The course's own material, apart from the library's computation: exercises and errata of the sources."""
