-- Views for people with SQL (SPEC 4) and the robot's own answers (SPEC 5.1).
-- Idempotent (CREATE OR REPLACE).

-- Every stored map with its border as a polygon.
CREATE OR REPLACE SQL SECURITY DEFINER VIEW v_maps AS
  SELECT id, name, mx1, my1, mx4, my4, border, source, obstacles, segments, imported_at,
         geo_crs, geo_tx, geo_ty, geo_rotation, geo_scale
  FROM maps;

-- Views over a table with a SPATIAL INDEX read that table first (STRAIGHT_JOIN): when
-- MariaDB 10.11 searches a spatial index after reading another table in the same
-- statement it fails with ERROR 1207 "Update locks cannot be acquired during a READ
-- UNCOMMITTED transaction" (MDEV-26123) -- exactly the inspector's MBRIntersects query.

-- Map segments with their obstacle and geometry: what QGIS or ogrinfo reads.
CREATE OR REPLACE SQL SECURITY DEFINER VIEW v_segments AS
  SELECT s.id, m.name AS map, o.obstacle_id, o.st, o.semantic AS obstacle_semantic,
         s.ord, s.ax, s.ay, s.bx, s.`by`, s.h, s.in_out, s.semantic, s.note, s.geom
  FROM segments s
  STRAIGHT_JOIN obstacles o ON o.map_id = s.map_id AND o.ord = s.obstacle_ord
  STRAIGHT_JOIN maps m ON m.id = s.map_id;

CREATE OR REPLACE SQL SECURITY DEFINER VIEW v_obstacles AS
  SELECT m.name AS map, o.ord, o.obstacle_id, o.st, o.semantic, o.cx, o.cy, o.r
  FROM obstacles o JOIN maps m ON m.id = o.map_id;

-- Current robot status: state, last pose, last seen, active task.
CREATE OR REPLACE SQL SECURITY DEFINER VIEW v_robot_status AS
  SELECT r.id AS robot_id, r.db_user AS name, m.name AS map, r.state, r.x, r.y, r.theta, r.v,
         r.last_seen, t.id AS task_id, t.state AS task_state, t.goal_x, t.goal_y
  FROM robots r
  LEFT JOIN maps m ON m.id = r.map_id
  LEFT JOIN tasks t ON t.id = (SELECT MAX(t2.id) FROM tasks t2 WHERE t2.robot_id = r.id)
  WHERE r.removed_at IS NULL;

CREATE OR REPLACE SQL SECURITY DEFINER VIEW v_tasks AS
  SELECT t.id, r.db_user AS robot, t.goal_x, t.goal_y, t.state, t.reason, t.created_at, t.updated_at
  FROM tasks t JOIN robots r ON r.id = t.robot_id;

-- Trajectories as points with timestamps.
CREATE OR REPLACE SQL SECURITY DEFINER VIEW v_trajectory_points AS
  SELECT tr.id, r.db_user AS robot, tr.t, tr.x, tr.y, tr.theta, tr.v, tr.w, tr.pos
  FROM trajectories tr STRAIGHT_JOIN robots r ON r.id = tr.robot_id;

-- Protocol traffic (payloads shown by size; SELECT UNCOMPRESS on sa for the text).
CREATE OR REPLACE SQL SECURITY DEFINER VIEW v_requests AS
  SELECT id, robot_id, db_user, op, params, OCTET_LENGTH(payload) AS payload_bytes, created_at FROM rr;
CREATE OR REPLACE SQL SECURITY DEFINER VIEW v_answers AS
  SELECT id, robot_id, db_user, request_id, op, params, OCTET_LENGTH(payload) AS payload_bytes, created_at FROM sa
  WHERE sentinel = 0;  -- a sentinel row is no answer (10_schema.sql)

-- Objects robots reported with SetObject, with who saw them and when.
CREATE OR REPLACE SQL SECURITY DEFINER VIEW v_observed_objects AS
  SELECT o.id, r.db_user AS robot, m.name AS map, o.t, o.x, o.y, o.object, o.pos
  FROM observed_objects o STRAIGHT_JOIN robots r ON r.id = o.robot_id LEFT JOIN maps m ON m.id = o.map_id;

CREATE OR REPLACE SQL SECURITY DEFINER VIEW v_gps_fixes AS
  SELECT g.id, r.db_user AS robot, g.t, g.lat, g.lon, g.x, g.y
  FROM gps_fixes g JOIN robots r ON r.id = g.robot_id;

-- Each robot sees and deletes only its own answers (SPEC 5.1, 9). Safe only with the
-- account-name rule and the binary no-pad collation of sa.db_user.
-- And locks only its own (SPEC 5.3): on sa's primary key a robot's DELETE ... WHERE id <= N
-- scans, and locks, every robot's rows up to N; on ix_sa_mine its scan stays in its own
-- (db_user, 0, id) range and ends at its own sentinel (db_user, 1, id), which no other
-- robot's scan reaches. FORCE INDEX: the optimizer otherwise picks PRIMARY.
CREATE OR REPLACE SQL SECURITY DEFINER VIEW sa_mine AS
  SELECT id, robot_id, db_user, request_id, op, params, payload, created_at
  FROM sa FORCE INDEX (ix_sa_mine)
  WHERE db_user = SUBSTRING_INDEX(USER(), '@', 1) AND sentinel = 0;

-- Each robot sees its own requests still waiting (ids and ops only; SPEC 5.3): a robot
-- whose connection broke during its INSERT cannot know whether it committed; it looks
-- here, and in sa_mine for an answer to it, before sending it again (client/robot_client.cpp,
-- docs/galera.md "Failover"). A plain read: it takes no lock the server waits on. ix_rr_user
-- serves it.
CREATE OR REPLACE SQL SECURITY DEFINER VIEW rr_mine AS
  SELECT id, op, created_at FROM rr WHERE db_user = SUBSTRING_INDEX(USER(), '@', 1);
