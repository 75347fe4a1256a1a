# The .deb (cpack -G DEB in the build folder): fleetmap_<version>_amd64.deb holding the
# programs, the client libraries with their headers and CMake package, sql/, the docs and
# the sample config, under /usr.
set(CPACK_PACKAGE_NAME fleetmap)
set(CPACK_PACKAGE_VENDOR "fleetmap")
set(CPACK_PACKAGE_CONTACT "fleetmap maintainers <fleetmap@example.org>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "GIS map service for robot fleets: server, operator CLI and robot client library")
string(CONCAT CPACK_PACKAGE_DESCRIPTION
  "fleetmap serves vector maps to robot fleets over MariaDB (RR/SA tables): fleetmap-server, "
  "the fleetmap operator command, the simulated robot fleetmap-robot, and the C++ client "
  "library a real robot links (find_package(fleetmap), fleetmap::client).")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)

set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # fleetmap_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${CPACK_PACKAGE_CONTACT}")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_HOMEPAGE "https://example.org/fleetmap")
# The programs' shared libraries (MySQL++, MariaDB client, spdlog, fmt, zlib) via dpkg-shlibdeps.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# What a consumer of the static client libraries compiles and links against: the headers
# fleetmap's public headers include, and what fleetmapConfig.cmake find_dependency()s.
set(CPACK_DEBIAN_PACKAGE_DEPENDS
  "libmysql++-dev, libmariadb-dev, nlohmann-json3-dev, libeigen3-dev, libboost-dev, libspdlog-dev, zlib1g-dev")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "mariadb-server, mariadb-client")
# fleetmap-web serves Leaflet from Debian's package (leaflet_dir); libssl comes in by
# dpkg-shlibdeps like the other shared libraries.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libjs-leaflet")

include(CPack)
