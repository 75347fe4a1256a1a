-- The semantic layer (issue 8, seed 002 section 3, seed 004 section II): what things are,
-- beside the segment map that says where walls are. Per stored map: environment objects
-- (a tag and one or more elements: a footprint POLYGON with an optional height range),
-- avoided areas (polygons no robot may enter) and the map's bounds polygon. Written by
-- 'fleetmap objects import' / 'avoid add' (operator) and by SetObject (server), read
-- through protocol/scene_store.h. Idempotent, like every file here.
--
-- Objects come from two sources:
--   imported  (source = 'imported', robot_id NULL): from a GeoJSON scene; never expire.
--             'objects import --replace' replaces them, and only them.
--   observed  (source = 'observed', robot_id set): a robot's SetObject; always dynamic,
--             stamped with robot and time (seen_at), deleted once expires_at passes unless
--             seen again (SceneStore::record_observation says what "again" means).
-- Tags, keys and labels compare byte for byte (utf8mb4_nopad_bin): 'Door' is not 'door',
-- nor 'door ' (a PAD SPACE collation such as utf8mb4_bin would say it is).
-- Geometry columns carry REF_SYSTEM_ID=0 (plain Cartesian metres; 'SRID 0' is a syntax
-- error in MariaDB 10.11, SPEC 9).

CREATE TABLE IF NOT EXISTS tags (
  tag         VARCHAR(64) CHARACTER SET utf8mb4 COLLATE utf8mb4_nopad_bin NOT NULL PRIMARY KEY,
  -- common/scene/scene.h TagInfo: what a planner or a person does with things of this tag
  class       ENUM('obstacle','landmark','interactable','dynamic') NOT NULL,
  description VARCHAR(255) NOT NULL DEFAULT '',
  -- ':' separates tag and id in segment semantics (common/slicing/scene_laser.h)
  CONSTRAINT ck_tags_tag CHECK (tag <> '' AND LOCATE(':', tag) = 0)
) ENGINE=InnoDB;

CREATE TABLE IF NOT EXISTS env_objects (
  id          BIGINT UNSIGNED NOT NULL AUTO_INCREMENT PRIMARY KEY,
  map_id      INT UNSIGNED NOT NULL,
  object_key  VARCHAR(255) CHARACTER SET utf8mb4 COLLATE utf8mb4_nopad_bin NOT NULL,  -- EnvObject::id
  tag         VARCHAR(64) CHARACTER SET utf8mb4 COLLATE utf8mb4_nopad_bin NOT NULL,
  dynamic     TINYINT(1) NOT NULL DEFAULT 0,
  source      ENUM('imported','observed') NOT NULL DEFAULT 'imported',
  robot_id    INT UNSIGNED NULL,              -- who observed it (observed objects only)
  label       VARCHAR(255) CHARACTER SET utf8mb4 COLLATE utf8mb4_nopad_bin NULL,  -- the robot's name for it (SetObject "object")
  seen_at     TIMESTAMP(6) NOT NULL DEFAULT CURRENT_TIMESTAMP(6),  -- import or last sighting
  expires_at  TIMESTAMP(6) NULL,              -- NULL: never (imported objects)
  UNIQUE KEY uq_env_objects_key (map_id, object_key),
  KEY ix_env_objects_tag (map_id, tag),
  KEY ix_env_objects_observed (map_id, robot_id, label),
  KEY ix_env_objects_expires (expires_at),
  CONSTRAINT fk_env_objects_map FOREIGN KEY (map_id) REFERENCES maps (id) ON DELETE CASCADE,
  CONSTRAINT fk_env_objects_tag FOREIGN KEY (tag) REFERENCES tags (tag),
  CONSTRAINT fk_env_objects_robot FOREIGN KEY (robot_id) REFERENCES robots (id),
  CONSTRAINT ck_env_objects_source CHECK (
    (source = 'imported' AND robot_id IS NULL AND expires_at IS NULL) OR
    (source = 'observed' AND robot_id IS NOT NULL AND dynamic = 1))
) ENGINE=InnoDB;

-- One row per element. map_id repeats the object's so that a spatial search filters by
-- map without a join (the spatial index covers every map, and map frames overlap).
CREATE TABLE IF NOT EXISTS object_elements (
  object_id   BIGINT UNSIGNED NOT NULL,
  ord         INT UNSIGNED NOT NULL,          -- position in the object, keeps export order
  map_id      INT UNSIGNED NOT NULL,
  footprint   POLYGON REF_SYSTEM_ID=0 NOT NULL,
  zmin        DOUBLE NULL,                    -- both NULL: a 2D element, blocks at every height
  zmax        DOUBLE NULL,
  PRIMARY KEY (object_id, ord),
  KEY ix_object_elements_map (map_id),
  SPATIAL INDEX sx_object_elements_footprint (footprint),
  CONSTRAINT fk_object_elements_object FOREIGN KEY (object_id) REFERENCES env_objects (id) ON DELETE CASCADE,
  CONSTRAINT ck_object_elements_z CHECK ((zmin IS NULL AND zmax IS NULL) OR (zmin < zmax))
) ENGINE=InnoDB;

CREATE TABLE IF NOT EXISTS avoided_areas (
  id          BIGINT UNSIGNED NOT NULL AUTO_INCREMENT PRIMARY KEY,
  map_id      INT UNSIGNED NOT NULL,
  area_key    VARCHAR(255) CHARACTER SET utf8mb4 COLLATE utf8mb4_nopad_bin NOT NULL,  -- AvoidedArea::id
  area        POLYGON REF_SYSTEM_ID=0 NOT NULL,
  created_at  TIMESTAMP(6) NOT NULL DEFAULT CURRENT_TIMESTAMP(6),
  UNIQUE KEY uq_avoided_areas_key (map_id, area_key),
  SPATIAL INDEX sx_avoided_areas_area (area),
  CONSTRAINT fk_avoided_areas_map FOREIGN KEY (map_id) REFERENCES maps (id) ON DELETE CASCADE
) ENGINE=InnoDB;

-- The map's bounds polygon (GeoJSON kind "bounds"): where robots may be, which can be
-- tighter than the rectangular border of the segment map. At most one per map.
CREATE TABLE IF NOT EXISTS map_bounds (
  map_id      INT UNSIGNED NOT NULL PRIMARY KEY,
  bounds      POLYGON REF_SYSTEM_ID=0 NOT NULL,
  CONSTRAINT fk_map_bounds_map FOREIGN KEY (map_id) REFERENCES maps (id) ON DELETE CASCADE
) ENGINE=InnoDB;

-- The default vocabulary (maps/example-room.tags.json); INSERT IGNORE keeps what an
-- operator changed with 'fleetmap tags set'. 'unknown' tags what a robot reported under
-- a name that is not a tag (its name is kept in env_objects.label).
INSERT IGNORE INTO tags (tag, class, description) VALUES
  ('box',             'obstacle',     'cardboard box on the floor'),
  ('table',           'obstacle',     'table; a laser below the top sees only the legs'),
  ('cupboard',        'obstacle',     'closed cupboard, floor to top'),
  ('chair',           'interactable', 'chair; may be pushed aside'),
  ('shelf',           'interactable', 'open shelving unit; items are picked from its boards'),
  ('door',            'landmark',     'door in a wall; a navigation landmark'),
  ('charging_station','landmark',     'robot charging station; a docking landmark'),
  ('trolley',         'dynamic',      'service trolley; moves during the day'),
  ('plant',           'obstacle',     'potted plant'),
  ('column',          'obstacle',     'structural column (usually an avoided area)'),
  ('wall',            'obstacle',     'wall (usually segments of the map, or an avoided area)'),
  ('unknown',         'dynamic',      'reported by a robot under a name that is not a tag');

-- Exact distance from a point to a polygon's area (0 inside or on the outline), for
-- people's queries. MariaDB 10.11's ST_Distance(polygon, point) is approximate: on 200
-- random boxes it was off on 9, by up to 0.17 m (its distance to a two-point LINESTRING
-- is exact, so this measures edge by edge). protocol/scene_store.cpp computes the same
-- distance in C++ (common/geometry/polygon.h distance_to_polygon).
DELIMITER //
CREATE OR REPLACE FUNCTION polygon_distance(poly GEOMETRY, p GEOMETRY) RETURNS DOUBLE
  DETERMINISTIC NO SQL SQL SECURITY INVOKER
  COMMENT 'exact distance from point p to polygon poly; 0 inside or on the outline'
BEGIN
  DECLARE ring GEOMETRY DEFAULT ST_ExteriorRing(poly);
  DECLARE n INT DEFAULT ST_NumPoints(ring);
  DECLARE i INT DEFAULT 1;
  DECLARE d DOUBLE DEFAULT NULL;
  IF poly IS NULL OR p IS NULL THEN RETURN NULL; END IF;
  IF ST_Intersects(poly, p) THEN RETURN 0; END IF;
  WHILE i < n DO
    SET d = LEAST(COALESCE(d, 1e308), ST_Distance(LineString(ST_PointN(ring, i), ST_PointN(ring, i + 1)), p));
    SET i = i + 1;
  END WHILE;
  RETURN d;
END//
DELIMITER ;

-- For people with SQL and GIS tools (SPEC 4). Live objects only: an observation past its
-- expires_at is gone for every reader even before the server's sweep deletes it.
-- Views that carry a spatial column read its table first (STRAIGHT_JOIN), see
-- 20_views.sql (MDEV-26123), and must merge into the query (ALGORITHM=MERGE) for its
-- MBRIntersects to reach the spatial index: a view that is materialized first is scanned
-- whole. ST_AsGeoJSON in a view's select list prevents merging (MariaDB 10.11 warning
-- 1354), so those views carry WKT; write ST_AsGeoJSON(footprint) in the query instead.

CREATE OR REPLACE ALGORITHM=MERGE SQL SECURITY DEFINER VIEW v_tags AS
  SELECT tag, class, description FROM tags;

-- One row per element, with its object, tag class and map: what a spatial query reads.
--   SELECT object_key, MIN(polygon_distance(footprint, POINT(2, 3))) AS d FROM v_object_elements
--   WHERE map = 'room' AND tag = 'door'
--     AND MBRIntersects(footprint, ST_GeomFromText('POLYGON((-8 -7,12 -7,12 13,-8 13,-8 -7))'))
--   GROUP BY object_key HAVING d <= 10 ORDER BY d;
CREATE OR REPLACE ALGORITHM=MERGE SQL SECURITY DEFINER VIEW v_object_elements AS
  SELECT e.object_id, m.name AS map, o.object_key, o.tag, t.class, o.dynamic, o.source,
         e.ord, e.zmin, e.zmax, e.footprint,
         ST_AsText(e.footprint) AS footprint_wkt
  FROM object_elements e
  STRAIGHT_JOIN env_objects o ON o.id = e.object_id
  STRAIGHT_JOIN tags t ON t.tag = o.tag
  STRAIGHT_JOIN maps m ON m.id = e.map_id
  WHERE o.expires_at IS NULL OR o.expires_at > NOW(6);

-- One row per object: tag class, who and when, and all its footprints as one
-- MULTIPOLYGON (WKT and GeoJSON). Materialized for each query (subqueries), so filter
-- spatially on v_object_elements.
CREATE OR REPLACE SQL SECURITY DEFINER VIEW v_objects AS
  SELECT o.id, m.name AS map, o.object_key, o.tag, t.class, o.dynamic, o.source,
         r.db_user AS robot, o.label, o.seen_at, o.expires_at,
         (SELECT COUNT(*) FROM object_elements e WHERE e.object_id = o.id) AS elements,
         (SELECT CONCAT('MULTIPOLYGON(', GROUP_CONCAT(SUBSTRING(ST_AsText(e.footprint), 8) ORDER BY e.ord), ')')
            FROM object_elements e WHERE e.object_id = o.id) AS footprint_wkt,
         (SELECT ST_AsGeoJSON(ST_GeomFromText(CONCAT('MULTIPOLYGON(',
                   GROUP_CONCAT(SUBSTRING(ST_AsText(e.footprint), 8) ORDER BY e.ord), ')')))
            FROM object_elements e WHERE e.object_id = o.id) AS footprint_geojson
  FROM env_objects o
  JOIN tags t ON t.tag = o.tag
  JOIN maps m ON m.id = o.map_id
  LEFT JOIN robots r ON r.id = o.robot_id
  WHERE o.expires_at IS NULL OR o.expires_at > NOW(6);

CREATE OR REPLACE ALGORITHM=MERGE SQL SECURITY DEFINER VIEW v_avoided_areas AS
  SELECT a.id, m.name AS map, a.area_key, a.area,
         ST_AsText(a.area) AS area_wkt, a.created_at
  FROM avoided_areas a
  STRAIGHT_JOIN maps m ON m.id = a.map_id;

CREATE OR REPLACE ALGORITHM=MERGE SQL SECURITY DEFINER VIEW v_map_bounds AS
  SELECT m.name AS map, b.bounds, ST_AsText(b.bounds) AS bounds_wkt
  FROM map_bounds b
  STRAIGHT_JOIN maps m ON m.id = b.map_id;

-- server: SetObject writes observations and the sweep deletes expired ones; reads the
-- rest (planning around avoided areas). operator: everything through the CLI.
-- inspector: the views only. robots: nothing.
GRANT SELECT ON tags TO fleetmap_server_role;
GRANT SELECT, INSERT, UPDATE, DELETE ON env_objects TO fleetmap_server_role;
GRANT SELECT, INSERT, UPDATE, DELETE ON object_elements TO fleetmap_server_role;
GRANT SELECT ON avoided_areas TO fleetmap_server_role;
GRANT SELECT ON map_bounds TO fleetmap_server_role;
GRANT SELECT, INSERT, UPDATE, DELETE ON tags TO fleetmap_operator_role;
GRANT SELECT, INSERT, UPDATE, DELETE ON env_objects TO fleetmap_operator_role;
GRANT SELECT, INSERT, UPDATE, DELETE ON object_elements TO fleetmap_operator_role;
GRANT SELECT, INSERT, UPDATE, DELETE ON avoided_areas TO fleetmap_operator_role;
GRANT SELECT, INSERT, UPDATE, DELETE ON map_bounds TO fleetmap_operator_role;
GRANT SELECT ON v_tags TO fleetmap_inspector_role;
GRANT SELECT ON v_objects TO fleetmap_inspector_role;
GRANT SELECT ON v_object_elements TO fleetmap_inspector_role;
GRANT SELECT ON v_avoided_areas TO fleetmap_inspector_role;
GRANT SELECT ON v_map_bounds TO fleetmap_inspector_role;
GRANT EXECUTE ON FUNCTION polygon_distance TO fleetmap_inspector_role;
GRANT EXECUTE ON FUNCTION polygon_distance TO fleetmap_operator_role;
GRANT EXECUTE ON FUNCTION polygon_distance TO fleetmap_server_role;
