# The version is set once, in project(VERSION) of CMakeLists.txt; the files that repeat
# it for readers must say the same: CITATION.cff (version:), CHANGELOG.md (a section
# "## [VERSION]") and README.md ("this version (VERSION)").
#   cmake -DVERSION=x.y.z -DSOURCE_DIR=... -P check_version.cmake
file(STRINGS ${SOURCE_DIR}/CITATION.cff citation_version REGEX "^version:")
if(NOT citation_version STREQUAL "version: ${VERSION}")
  message(FATAL_ERROR "CITATION.cff says '${citation_version}', project(VERSION) is ${VERSION}")
endif()
file(STRINGS ${SOURCE_DIR}/CHANGELOG.md changelog_section REGEX "^## \\[${VERSION}\\]")
if(NOT changelog_section)
  message(FATAL_ERROR "CHANGELOG.md has no section '## [${VERSION}]' for project(VERSION) ${VERSION}")
endif()
file(STRINGS ${SOURCE_DIR}/README.md readme_version REGEX "this version \\(")
if(NOT readme_version MATCHES "this version \\(${VERSION}\\)")
  message(FATAL_ERROR "README.md says '${readme_version}', project(VERSION) is ${VERSION}")
endif()
message(STATUS "version ${VERSION}: CITATION.cff, CHANGELOG.md and README.md agree")
