# scratch: scene definitions (merged into build.py later)
