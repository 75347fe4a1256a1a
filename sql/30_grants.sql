-- Roles and what each may do (SPEC 4). Accounts get one role each:
--   scripts/db.sh creates fleetmap_server, fleetmap_operator and fleetmap_inspector;
--   'fleetmap robot add' creates one account per robot with fleetmap_robot_role.
-- Idempotent. Grants name tables of the current database.

CREATE ROLE IF NOT EXISTS fleetmap_server_role;
CREATE ROLE IF NOT EXISTS fleetmap_operator_role;
CREATE ROLE IF NOT EXISTS fleetmap_inspector_role;
CREATE ROLE IF NOT EXISTS fleetmap_robot_role;

-- server: everything the daemon needs, plus finding and ending a robot connection
-- that stalls others (SPEC 5.3).
GRANT SELECT, INSERT, UPDATE, DELETE ON maps TO fleetmap_server_role;
GRANT SELECT, INSERT, UPDATE, DELETE ON obstacles TO fleetmap_server_role;
GRANT SELECT, INSERT, UPDATE, DELETE ON segments TO fleetmap_server_role;
GRANT SELECT, INSERT, UPDATE, DELETE ON robots TO fleetmap_server_role;
GRANT SELECT, INSERT, UPDATE, DELETE ON tasks TO fleetmap_server_role;
GRANT SELECT, INSERT, UPDATE, DELETE ON trajectories TO fleetmap_server_role;
GRANT SELECT, INSERT, UPDATE, DELETE ON rr TO fleetmap_server_role;
GRANT SELECT, INSERT, UPDATE, DELETE ON sa TO fleetmap_server_role;
GRANT SELECT, INSERT, UPDATE, DELETE ON gps_fixes TO fleetmap_server_role;
GRANT SELECT, INSERT, UPDATE, DELETE ON images TO fleetmap_server_role;
GRANT SELECT, INSERT, UPDATE, DELETE ON observed_objects TO fleetmap_server_role;
GRANT PROCESS, CONNECTION ADMIN ON *.* TO fleetmap_server_role;

-- operator: import and edit maps, register robots, set goals, initial poses, aborts.
GRANT SELECT, INSERT, UPDATE, DELETE ON maps TO fleetmap_operator_role;
GRANT SELECT, INSERT, UPDATE, DELETE ON obstacles TO fleetmap_operator_role;
GRANT SELECT, INSERT, UPDATE, DELETE ON segments TO fleetmap_operator_role;
GRANT SELECT, INSERT, UPDATE ON robots TO fleetmap_operator_role;
GRANT SELECT, INSERT, UPDATE ON tasks TO fleetmap_operator_role;
GRANT SELECT ON trajectories TO fleetmap_operator_role;
GRANT SELECT ON gps_fixes TO fleetmap_operator_role;
GRANT SELECT ON observed_objects TO fleetmap_operator_role;
GRANT SELECT ON v_robot_status TO fleetmap_operator_role;
GRANT SELECT ON v_tasks TO fleetmap_operator_role;
GRANT SELECT ON v_trajectory_points TO fleetmap_operator_role;
GRANT SELECT ON v_observed_objects TO fleetmap_operator_role;

-- inspector: SELECT on the views for people, nothing else.
GRANT SELECT ON v_maps TO fleetmap_inspector_role;
GRANT SELECT ON v_segments TO fleetmap_inspector_role;
GRANT SELECT ON v_obstacles TO fleetmap_inspector_role;
GRANT SELECT ON v_robot_status TO fleetmap_inspector_role;
GRANT SELECT ON v_tasks TO fleetmap_inspector_role;
GRANT SELECT ON v_trajectory_points TO fleetmap_inspector_role;
GRANT SELECT ON v_requests TO fleetmap_inspector_role;
GRANT SELECT ON v_answers TO fleetmap_inspector_role;
GRANT SELECT ON v_observed_objects TO fleetmap_inspector_role;
GRANT SELECT ON v_gps_fixes TO fleetmap_inspector_role;

-- robot: INSERT requests; read and delete its own answers only (SPEC 5.1); see which of
-- its own requests still wait (rr_mine: after a lost connection, was the INSERT committed?).
GRANT INSERT ON rr TO fleetmap_robot_role;
GRANT SELECT, DELETE ON sa_mine TO fleetmap_robot_role;
GRANT SELECT ON rr_mine TO fleetmap_robot_role;
