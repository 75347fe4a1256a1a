-- Control points of a map's georeference (docs/georeference.md): the places, known both
-- in the map frame and in WGS 84, that 'fleetmap map georef NAME --control ...' fitted
-- the georeference (maps.geo_*) to, with each one's residual after the fit. They
-- describe the georeference stored now: setting another one deletes them
-- (protocol/map_store.cpp set_georef), deleting the map deletes them (cascade).
-- Idempotent, like every file here.

CREATE TABLE IF NOT EXISTS georef_control_points (
  map_id      INT UNSIGNED NOT NULL,
  ord         INT UNSIGNED NOT NULL,          -- 1, 2, ... in the order given
  x           DOUBLE NOT NULL,                -- map frame, metres
  y           DOUBLE NOT NULL,
  lat         DOUBLE NOT NULL,                -- WGS 84, degrees
  lon         DOUBLE NOT NULL,
  residual_m  DOUBLE NOT NULL,                -- ground distance between fitted and given position
  PRIMARY KEY (map_id, ord),
  CONSTRAINT fk_georef_control_points_map FOREIGN KEY (map_id) REFERENCES maps (id) ON DELETE CASCADE,
  CONSTRAINT ck_georef_control_points_fix CHECK (lat BETWEEN -90 AND 90 AND lon BETWEEN -180 AND 180)
) ENGINE=InnoDB;

-- For people with SQL: the points by map name.
CREATE OR REPLACE SQL SECURITY DEFINER VIEW v_georef_control_points AS
  SELECT m.name AS map, c.map_id, c.ord, c.x, c.y, c.lat, c.lon, c.residual_m
  FROM georef_control_points c JOIN maps m ON m.id = c.map_id;

-- operator: fits and clears georeferences. server: nothing (SendGPS reads maps.geo_*
-- only). inspector: the view. robots: nothing.
GRANT SELECT, INSERT, DELETE ON georef_control_points TO fleetmap_operator_role;
GRANT SELECT ON v_georef_control_points TO fleetmap_operator_role;
GRANT SELECT ON v_georef_control_points TO fleetmap_inspector_role;
