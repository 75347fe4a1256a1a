-- Brings a database created by an earlier fleetmap up to the current schema.
-- Idempotent: every step is ADD ... IF NOT EXISTS (10_schema.sql already has them all
-- for a new database, so on a new database nothing here changes anything).

-- server issue: sessions, pushed aborts, georeferenced maps
ALTER TABLE robots ADD COLUMN IF NOT EXISTS session_at TIMESTAMP(6) NULL AFTER magic;
ALTER TABLE tasks ADD COLUMN IF NOT EXISTS abort_requested_at TIMESTAMP(6) NULL AFTER answer_id;
ALTER TABLE tasks ADD COLUMN IF NOT EXISTS abort_answer_id BIGINT UNSIGNED NULL AFTER abort_requested_at;
ALTER TABLE maps ADD COLUMN IF NOT EXISTS geo_lat DOUBLE NULL AFTER imported_at;
ALTER TABLE maps ADD COLUMN IF NOT EXISTS geo_lon DOUBLE NULL AFTER geo_lat;
ALTER TABLE maps ADD COLUMN IF NOT EXISTS geo_heading DOUBLE NULL AFTER geo_lon;

-- semantic layer (issue 8): robot profiles
ALTER TABLE robots ADD COLUMN IF NOT EXISTS laser_height DOUBLE NULL AFTER removed_at;
ALTER TABLE robots ADD COLUMN IF NOT EXISTS radius DOUBLE NULL AFTER laser_height;
ALTER TABLE robots ADD COLUMN IF NOT EXISTS body_height DOUBLE NULL AFTER radius;
ALTER TABLE robots ADD COLUMN IF NOT EXISTS can_stairs BOOLEAN NOT NULL DEFAULT FALSE AFTER body_height;
ALTER TABLE robots ADD COLUMN IF NOT EXISTS can_ramps BOOLEAN NOT NULL DEFAULT TRUE AFTER can_stairs;

-- GIS issue: a georeference is a CRS plus a similarity (common/map/map_georef.h). An
-- origin + heading of the earlier columns becomes the local Transverse Mercator at the
-- origin, rotated by the heading (common/gis/geo_transform.cpp local_tm_crs); then the
-- earlier columns go.
ALTER TABLE maps ADD COLUMN IF NOT EXISTS geo_crs TEXT NULL AFTER imported_at;
ALTER TABLE maps ADD COLUMN IF NOT EXISTS geo_tx DOUBLE NULL AFTER geo_crs;
ALTER TABLE maps ADD COLUMN IF NOT EXISTS geo_ty DOUBLE NULL AFTER geo_tx;
ALTER TABLE maps ADD COLUMN IF NOT EXISTS geo_rotation DOUBLE NULL AFTER geo_ty;
ALTER TABLE maps ADD COLUMN IF NOT EXISTS geo_scale DOUBLE NULL AFTER geo_rotation;
UPDATE maps SET geo_crs = CONCAT('+proj=tmerc +lat_0=', geo_lat, ' +lon_0=', geo_lon,
                                 ' +k=1 +x_0=0 +y_0=0 +ellps=WGS84 +units=m +type=crs'),
                geo_tx = 0, geo_ty = 0, geo_rotation = COALESCE(geo_heading, 0), geo_scale = 1
  WHERE geo_lat IS NOT NULL AND geo_lon IS NOT NULL AND geo_crs IS NULL;
ALTER TABLE maps DROP COLUMN IF EXISTS geo_lat, DROP COLUMN IF EXISTS geo_lon, DROP COLUMN IF EXISTS geo_heading;

-- Replace without loss: a replaced map keeps its row and counts its imports
-- (protocol/map_replace.h).
ALTER TABLE maps ADD COLUMN IF NOT EXISTS revision INT UNSIGNED NOT NULL DEFAULT 1 AFTER imported_at;

-- GIS import: an obstacle's semantic keeps every attribute of its feature (seed 001
-- section III; docs/gis-import.md), and OSM relations exceed 1 KiB.
ALTER TABLE obstacles MODIFY semantic TEXT NOT NULL DEFAULT '';

-- Robots lock only their own answers (SPEC 5.3): sa_mine forces ix_sa_mine, whose range of
-- each robot ends at the robot's sentinel row (10_schema.sql). ix_sa_user (db_user, id)
-- goes: no query of the server uses it, and ix_sa_mine serves db_user lookups.
ALTER TABLE sa ADD COLUMN IF NOT EXISTS sentinel TINYINT NOT NULL DEFAULT 0 AFTER created_at,
  ADD KEY IF NOT EXISTS ix_sa_mine (db_user, sentinel, id),
  DROP KEY IF EXISTS ix_sa_user;
-- One sentinel for every robot not removed that has none (robot_add makes it for new ones).
INSERT INTO sa (robot_id, db_user, request_id, op, params, payload, created_at, sentinel)
  SELECT r.id, r.db_user, NULL, 'End', '{}', NULL, SYSDATE(6), 1 FROM robots r
  WHERE r.removed_at IS NULL
    AND NOT EXISTS (SELECT 1 FROM sa WHERE sa.db_user = r.db_user AND sa.sentinel = 1);

-- 'localizing': the robot's own localization reported its pose lost (SendPos "status":
-- "lost", docs/protocol.md); it stays until the robot reports a pose again.
ALTER TABLE robots MODIFY state ENUM('offline','ready','moving','stopped','lost','localizing') NOT NULL DEFAULT 'offline';
