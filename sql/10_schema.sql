-- fleetmap schema: maps, robots, tasks, trajectories and the RR/SA protocol tables (SPEC 4-5).
-- Idempotent: loaded by scripts/db.sh start on every start, and by hand on a real server:
--   mariadb fleetmap < sql/10_schema.sql
-- Coordinates are metres in the map frame; geometry columns carry REF_SYSTEM_ID=0
-- (a plain Cartesian frame; 'SRID 0' is a syntax error in MariaDB 10.11, SPEC 9).

CREATE TABLE IF NOT EXISTS maps (
  id          INT UNSIGNED NOT NULL AUTO_INCREMENT PRIMARY KEY,
  name        VARCHAR(64)  NOT NULL,
  -- seed 000 appendix A: (mx1,my1) upper-left, (mx4,my4) lower-right
  mx1         DOUBLE NOT NULL,
  my1         DOUBLE NOT NULL,
  mx4         DOUBLE NOT NULL,
  my4         DOUBLE NOT NULL,
  border      POLYGON REF_SYSTEM_ID=0 NOT NULL,
  source      VARCHAR(255) NOT NULL DEFAULT '',
  obstacles   INT UNSIGNED NOT NULL DEFAULT 0,
  segments    INT UNSIGNED NOT NULL DEFAULT 0,
  imported_at TIMESTAMP(6) NOT NULL DEFAULT CURRENT_TIMESTAMP(6),
  -- imports under this id: 'map import --replace' keeps the row (robots, objects, graph
  -- stay attached) and adds one; caches of the map's contents compare it
  revision    INT UNSIGNED NOT NULL DEFAULT 1,
  -- georeference (optional, common/map/map_georef.h): the base CRS as PROJ reads it and
  -- the similarity base = (tx, ty) + scale * R(rotation) * map; SendGPS fixes and WGS 84
  -- exports go through it. All NULL or all set.
  geo_crs      TEXT NULL,
  geo_tx       DOUBLE NULL,
  geo_ty       DOUBLE NULL,
  geo_rotation DOUBLE NULL,
  geo_scale    DOUBLE NULL,
  UNIQUE KEY uq_maps_name (name)
) ENGINE=InnoDB;

CREATE TABLE IF NOT EXISTS obstacles (
  map_id      INT UNSIGNED NOT NULL,
  ord         INT UNSIGNED NOT NULL,          -- position in the map file, keeps export order
  obstacle_id INT NOT NULL,                   -- the file's id
  st          TINYINT UNSIGNED NOT NULL,      -- shape type 1..6
  semantic    TEXT NOT NULL DEFAULT '',       -- every attribute of a GIS feature (docs/gis-import.md)
  -- minimum bounding circle, computed once at import (seed 000 section 4.1)
  cx          DOUBLE NOT NULL,
  cy          DOUBLE NOT NULL,
  r           DOUBLE NOT NULL,
  PRIMARY KEY (map_id, ord),
  CONSTRAINT fk_obstacles_map FOREIGN KEY (map_id) REFERENCES maps (id) ON DELETE CASCADE,
  CONSTRAINT ck_obstacles_st CHECK (st BETWEEN 1 AND 6)
) ENGINE=InnoDB;

CREATE TABLE IF NOT EXISTS segments (
  id           BIGINT UNSIGNED NOT NULL AUTO_INCREMENT PRIMARY KEY,
  map_id       INT UNSIGNED NOT NULL,
  obstacle_ord INT UNSIGNED NOT NULL,
  ord          INT UNSIGNED NOT NULL,         -- position inside the obstacle (segments are oriented)
  ax           DOUBLE NOT NULL,
  ay           DOUBLE NOT NULL,
  bx           DOUBLE NOT NULL,
  `by`         DOUBLE NOT NULL,
  h            DOUBLE NOT NULL,
  in_out       TINYINT UNSIGNED NOT NULL,     -- 0 indoor, 1 outdoor
  semantic     VARCHAR(1024) NOT NULL DEFAULT '',
  note         VARCHAR(1024) NOT NULL DEFAULT '',  -- the trailing '%...' comment of the seed format
  geom         LINESTRING REF_SYSTEM_ID=0 NOT NULL,
  SPATIAL INDEX sx_segments_geom (geom),
  KEY ix_segments_obstacle (map_id, obstacle_ord, ord),
  CONSTRAINT fk_segments_obstacle FOREIGN KEY (map_id, obstacle_ord)
    REFERENCES obstacles (map_id, ord) ON DELETE CASCADE,
  CONSTRAINT ck_segments_in_out CHECK (in_out IN (0, 1))
) ENGINE=InnoDB;

CREATE TABLE IF NOT EXISTS robots (
  id          INT UNSIGNED NOT NULL AUTO_INCREMENT PRIMARY KEY,
  -- account name: [a-z0-9_-]{1,32}, binary no-pad so 'R1' or 'r1 ' never match 'r1' (SPEC 5.1)
  db_user     VARCHAR(80) CHARACTER SET utf8mb4 COLLATE utf8mb4_nopad_bin NOT NULL,
  map_id      INT UNSIGNED NULL,
  state       ENUM('offline','ready','moving','stopped','lost','localizing') NOT NULL DEFAULT 'offline',
  magic       BIGINT NULL,                    -- of the current session (last Ready); NULL: never registered
  session_at  TIMESTAMP(6) NULL,
  x           DOUBLE NULL,
  y           DOUBLE NULL,
  theta       DOUBLE NULL,
  v           DOUBLE NULL,
  ini_x       DOUBLE NULL,
  ini_y       DOUBLE NULL,
  ini_theta   DOUBLE NULL,
  last_seen   TIMESTAMP(6) NULL,
  created_at  TIMESTAMP(6) NOT NULL DEFAULT CURRENT_TIMESTAMP(6),
  removed_at  TIMESTAMP(6) NULL,
  -- profile (issue 8, seed 004): what the robot's map and plans depend on; NULL: the
  -- server's defaults (robot_radius_m, body_height_m in [server]); no laser height: the
  -- robot gets the stored map unsliced
  laser_height DOUBLE NULL,                   -- m over the floor, of the laser its maps are sliced for
  radius      DOUBLE NULL,                    -- m, kept from every obstacle when planning
  body_height DOUBLE NULL,                    -- m: elements starting below this block it
  can_stairs  BOOLEAN NOT NULL DEFAULT FALSE,
  can_ramps   BOOLEAN NOT NULL DEFAULT TRUE,
  UNIQUE KEY uq_robots_db_user (db_user),
  CONSTRAINT fk_robots_map FOREIGN KEY (map_id) REFERENCES maps (id) ON DELETE SET NULL,
  CONSTRAINT ck_robots_name CHECK (db_user REGEXP '^[a-z0-9_-]{1,32}$'),
  CONSTRAINT ck_robots_profile CHECK ((laser_height IS NULL OR laser_height BETWEEN 0 AND 1000)
                                      AND (radius IS NULL OR radius BETWEEN 0 AND 100)
                                      AND (body_height IS NULL OR body_height BETWEEN 0 AND 1000))
) ENGINE=InnoDB;

CREATE TABLE IF NOT EXISTS tasks (
  id          BIGINT UNSIGNED NOT NULL AUTO_INCREMENT PRIMARY KEY,
  robot_id    INT UNSIGNED NOT NULL,
  goal_x      DOUBLE NOT NULL,
  goal_y      DOUBLE NOT NULL,
  state       ENUM('assigned','acknowledged','active','done','aborted','failed') NOT NULL DEFAULT 'assigned',
  answer_id   BIGINT UNSIGNED NULL,           -- the sa row that pushed SetPosEnd (NULL: not pushed yet)
  abort_requested_at TIMESTAMP(6) NULL,       -- an operator asked to abort
  abort_answer_id BIGINT UNSIGNED NULL,       -- the sa row that pushed Abort
  reason      VARCHAR(255) NOT NULL DEFAULT '',
  created_at  TIMESTAMP(6) NOT NULL DEFAULT CURRENT_TIMESTAMP(6),
  updated_at  TIMESTAMP(6) NOT NULL DEFAULT CURRENT_TIMESTAMP(6) ON UPDATE CURRENT_TIMESTAMP(6),
  KEY ix_tasks_robot (robot_id, state),
  CONSTRAINT fk_tasks_robot FOREIGN KEY (robot_id) REFERENCES robots (id)
) ENGINE=InnoDB;

CREATE TABLE IF NOT EXISTS trajectories (
  id          BIGINT UNSIGNED NOT NULL AUTO_INCREMENT PRIMARY KEY,
  robot_id    INT UNSIGNED NOT NULL,
  t           TIMESTAMP(6) NOT NULL,
  x           DOUBLE NOT NULL,
  y           DOUBLE NOT NULL,
  theta       DOUBLE NOT NULL,
  v           DOUBLE NOT NULL,
  w           DOUBLE NULL,
  pos         POINT REF_SYSTEM_ID=0 NOT NULL,
  KEY ix_trajectories_robot_t (robot_id, t),
  SPATIAL INDEX sx_trajectories_pos (pos),
  CONSTRAINT fk_trajectories_robot FOREIGN KEY (robot_id) REFERENCES robots (id)
) ENGINE=InnoDB;

CREATE TABLE IF NOT EXISTS gps_fixes (
  id          BIGINT UNSIGNED NOT NULL AUTO_INCREMENT PRIMARY KEY,
  robot_id    INT UNSIGNED NOT NULL,
  t           TIMESTAMP(6) NOT NULL,
  lat         DOUBLE NOT NULL,
  lon         DOUBLE NOT NULL,
  x           DOUBLE NULL,                    -- map coordinates when the map is georeferenced
  y           DOUBLE NULL,
  KEY ix_gps_robot_t (robot_id, t),
  CONSTRAINT fk_gps_robot FOREIGN KEY (robot_id) REFERENCES robots (id)
) ENGINE=InnoDB;

CREATE TABLE IF NOT EXISTS images (
  id          BIGINT UNSIGNED NOT NULL AUTO_INCREMENT PRIMARY KEY,
  robot_id    INT UNSIGNED NOT NULL,
  t           TIMESTAMP(6) NOT NULL,
  x           DOUBLE NOT NULL,
  y           DOUBLE NOT NULL,
  object_id   BIGINT NULL,
  format      VARCHAR(32) NOT NULL,
  data        LONGBLOB NOT NULL,
  KEY ix_images_robot_t (robot_id, t),
  CONSTRAINT fk_images_robot FOREIGN KEY (robot_id) REFERENCES robots (id)
) ENGINE=InnoDB;

-- Objects robots observed (SetObject); the semantic layer builds on this.
CREATE TABLE IF NOT EXISTS observed_objects (
  id          BIGINT UNSIGNED NOT NULL AUTO_INCREMENT PRIMARY KEY,
  robot_id    INT UNSIGNED NOT NULL,
  map_id      INT UNSIGNED NULL,
  t           TIMESTAMP(6) NOT NULL,
  x           DOUBLE NOT NULL,
  y           DOUBLE NOT NULL,
  object      VARCHAR(255) NOT NULL,
  pos         POINT REF_SYSTEM_ID=0 NOT NULL,
  SPATIAL INDEX sx_observed_pos (pos),
  KEY ix_observed_robot_t (robot_id, t),
  CONSTRAINT fk_observed_robot FOREIGN KEY (robot_id) REFERENCES robots (id)
) ENGINE=InnoDB;

-- RR/SA protocol (SPEC 5.1). Column names and types are the protocol: do not rename.
CREATE TABLE IF NOT EXISTS rr (
  id          BIGINT UNSIGNED NOT NULL AUTO_INCREMENT PRIMARY KEY,
  robot_id    INT UNSIGNED NULL,
  db_user     VARCHAR(80) CHARACTER SET utf8mb4 COLLATE utf8mb4_nopad_bin NOT NULL DEFAULT '',
  op          VARCHAR(16) NOT NULL,
  params      JSON NOT NULL,
  payload     LONGBLOB NULL,
  created_at  TIMESTAMP(6) NOT NULL DEFAULT CURRENT_TIMESTAMP(6),
  KEY ix_rr_user (db_user, id)
) ENGINE=InnoDB;

CREATE TABLE IF NOT EXISTS sa (
  id          BIGINT UNSIGNED NOT NULL AUTO_INCREMENT PRIMARY KEY,
  robot_id    INT UNSIGNED NOT NULL,
  db_user     VARCHAR(80) CHARACTER SET utf8mb4 COLLATE utf8mb4_nopad_bin NOT NULL,
  request_id  BIGINT UNSIGNED NULL,
  op          VARCHAR(16) NOT NULL,
  params      JSON NOT NULL,
  payload     LONGBLOB NULL,
  created_at  TIMESTAMP(6) NOT NULL DEFAULT CURRENT_TIMESTAMP(6),
  -- One row per robot with sentinel = 1 (op 'End', made by robot_add) ends the robot's
  -- range in ix_sa_mine, the index sa_mine forces: a robot's locking scan of its answers
  -- stops at its own sentinel and never locks, nor waits on, the next robot's rows
  -- (SPEC 5.3: no robot can stall another). Not an answer: nothing reads it.
  sentinel    TINYINT NOT NULL DEFAULT 0,
  KEY ix_sa_mine (db_user, sentinel, id)
) ENGINE=InnoDB;

-- The database, not the robot, says who sent a request and when (SPEC 5.1, 9):
-- db_user from the account, created_at from SYSDATE(6) (a robot can SET timestamp),
-- id from AUTO_INCREMENT (a robot-chosen id could exhaust the counter for everyone;
-- so could SET insert_id, which NEW.id = NULL does not override: refused outright).
DELIMITER //
CREATE OR REPLACE TRIGGER rr_stamp BEFORE INSERT ON rr FOR EACH ROW
BEGIN
  IF @@session.insert_id <> 0 THEN
    SIGNAL SQLSTATE '45000' SET MESSAGE_TEXT = 'rr: SET insert_id is not allowed';
  END IF;
  SET NEW.db_user = SUBSTRING_INDEX(USER(), '@', 1),
      NEW.id = NULL,
      NEW.created_at = SYSDATE(6);
END//
DELIMITER ;
