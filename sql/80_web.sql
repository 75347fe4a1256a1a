-- The web console's own account (server/web, fleetmap-web): what it reads for every
-- signed-in person, and nothing it could write. People sign in with their own operator
-- or inspector account (SPEC 4); a write runs on that person's own connection, so the
-- database's grants, not the web tier, decide what each may change. The reads here are
-- the inspector's (the map, robots, tasks, trajectories, topology, the semantic layer),
-- taken from the tables the stores read rather than the views.
CREATE ROLE IF NOT EXISTS fleetmap_web_role;
GRANT SELECT ON maps TO fleetmap_web_role;
GRANT SELECT ON obstacles TO fleetmap_web_role;
GRANT SELECT ON segments TO fleetmap_web_role;
GRANT SELECT ON robots TO fleetmap_web_role;
GRANT SELECT ON tasks TO fleetmap_web_role;
GRANT SELECT ON trajectories TO fleetmap_web_role;
GRANT SELECT ON gps_fixes TO fleetmap_web_role;
GRANT SELECT ON topo_graphs TO fleetmap_web_role;
GRANT SELECT ON topo_nodes TO fleetmap_web_role;
GRANT SELECT ON topo_edges TO fleetmap_web_role;
GRANT SELECT ON georef_control_points TO fleetmap_web_role;
GRANT SELECT ON tags TO fleetmap_web_role;
GRANT SELECT ON env_objects TO fleetmap_web_role;
GRANT SELECT ON object_elements TO fleetmap_web_role;
GRANT SELECT ON avoided_areas TO fleetmap_web_role;
GRANT SELECT ON map_bounds TO fleetmap_web_role;
GRANT SELECT ON observed_objects TO fleetmap_web_role;
GRANT SELECT ON v_robot_status TO fleetmap_web_role;
GRANT SELECT ON v_tasks TO fleetmap_web_role;
