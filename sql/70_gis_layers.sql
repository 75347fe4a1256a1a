-- The database as GIS layers (docs/gis-layers.md, protocol/gis_layers.h): a second
-- database, <this database>_gis, holding one table per layer with an integer primary
-- key (the FID GDAL's MySQL driver takes from DESCRIBE: a view has none) and one
-- geometry column, and the OGC metadata GDAL reads in MariaDB:
--   geometry_columns  f_table_name -> type, coord_dimension, srid
--   spatial_ref_sys   srid -> srtext (OGC WKT)
-- 'fleetmap map import|delete|georef' rebuild the tables (DDL: outside any transaction).
-- A separate database keeps the DDL the operator needs for that away from the fleet's
-- tables, and gives GIS tools a connection that lists layers only.
-- Idempotent, like every file here; names built from DATABASE() by EXECUTE IMMEDIATE.

EXECUTE IMMEDIATE CONCAT('CREATE DATABASE IF NOT EXISTS `', DATABASE(), '_gis` ',
  'CHARACTER SET utf8mb4 COLLATE utf8mb4_unicode_ci');

-- As GDAL creates them (ogr/ogrsf_frmts/mysql, InitializeMetadataTables), with keys;
-- srtext is TEXT: a derived CRS's WKT2 is longer than GDAL's VARCHAR(2048).
EXECUTE IMMEDIATE CONCAT('CREATE TABLE IF NOT EXISTS `', DATABASE(), '_gis`.geometry_columns (',
  'F_TABLE_CATALOG VARCHAR(256) NULL, F_TABLE_SCHEMA VARCHAR(256) NULL, ',
  'F_TABLE_NAME VARCHAR(64) NOT NULL PRIMARY KEY, F_GEOMETRY_COLUMN VARCHAR(64) NOT NULL, ',
  'COORD_DIMENSION INT NULL, SRID INT NULL, TYPE VARCHAR(32) NOT NULL) ENGINE=InnoDB');
EXECUTE IMMEDIATE CONCAT('CREATE TABLE IF NOT EXISTS `', DATABASE(), '_gis`.spatial_ref_sys (',
  'SRID INT NOT NULL PRIMARY KEY, AUTH_NAME VARCHAR(256) NULL, AUTH_SRID INT NULL, SRTEXT TEXT NULL) ENGINE=InnoDB');

-- WGS 84 for the GPS layer (x = longitude: GDAL reads it in GIS axis order).
EXECUTE IMMEDIATE CONCAT('INSERT IGNORE INTO `', DATABASE(), '_gis`.spatial_ref_sys VALUES (4326, ''EPSG'', 4326, ',
  '''GEOGCS["WGS 84",DATUM["WGS_1984",SPHEROID["WGS 84",6378137,298.257223563,AUTHORITY["EPSG","7030"]],',
  'AUTHORITY["EPSG","6326"]],PRIMEM["Greenwich",0,AUTHORITY["EPSG","8901"]],',
  'UNIT["degree",0.0174532925199433,AUTHORITY["EPSG","9122"]],AXIS["Latitude",NORTH],AXIS["Longitude",EAST],',
  'AUTHORITY["EPSG","4326"]]'')');

-- operator: 'fleetmap map ...' rebuilds layers (tables built aside, swapped by RENAME).
-- inspector: reads them. server and robots: nothing (robots see their answers only, SPEC 9).
EXECUTE IMMEDIATE CONCAT('GRANT SELECT, INSERT, UPDATE, DELETE, CREATE, DROP, ALTER, INDEX ON `', DATABASE(),
  '_gis`.* TO fleetmap_operator_role');
EXECUTE IMMEDIATE CONCAT('GRANT SELECT ON `', DATABASE(), '_gis`.* TO fleetmap_inspector_role');
