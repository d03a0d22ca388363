# Empty compiler generated dependencies file for test_first_episode.
# This may be replaced when dependencies are built.
