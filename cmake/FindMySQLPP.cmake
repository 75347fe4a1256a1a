# FindMySQLPP: MySQL++ and the MariaDB client library it wraps. Debian ships neither a
# CMake package nor a pkg-config file for MySQL++, so fleetmap finds it here, in-tree and
# from the installed fleetmapConfig.cmake alike.
#
# Imported target:
#   MySQLPP::MySQLPP   libmysqlpp, its headers and the MariaDB client headers (mysql++
#                      includes <mysql.h>), linking the MariaDB client library.
# Variables: MySQLPP_FOUND, MySQLPP_INCLUDE_DIR, MySQLPP_LIBRARY, MySQLPP_MARIADB_INCLUDE_DIR,
#            MySQLPP_MARIADB_LIBRARY.
include(FindPackageHandleStandardArgs)

find_path(MySQLPP_INCLUDE_DIR mysql++/mysql++.h)
find_library(MySQLPP_LIBRARY mysqlpp)
find_path(MySQLPP_MARIADB_INCLUDE_DIR mysql.h PATH_SUFFIXES mariadb mysql)
find_library(MySQLPP_MARIADB_LIBRARY NAMES mariadb mysqlclient)
mark_as_advanced(MySQLPP_INCLUDE_DIR MySQLPP_LIBRARY MySQLPP_MARIADB_INCLUDE_DIR MySQLPP_MARIADB_LIBRARY)

find_package_handle_standard_args(MySQLPP
  REQUIRED_VARS MySQLPP_LIBRARY MySQLPP_INCLUDE_DIR MySQLPP_MARIADB_LIBRARY MySQLPP_MARIADB_INCLUDE_DIR)

if(MySQLPP_FOUND AND NOT TARGET MySQLPP::MySQLPP)
  add_library(MySQLPP::MySQLPP UNKNOWN IMPORTED)
  set_target_properties(MySQLPP::MySQLPP PROPERTIES
    IMPORTED_LOCATION "${MySQLPP_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${MySQLPP_INCLUDE_DIR};${MySQLPP_MARIADB_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${MySQLPP_MARIADB_LIBRARY}")
endif()
