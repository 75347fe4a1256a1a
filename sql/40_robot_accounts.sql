-- Robot accounts (SPEC 4, 5.1), created and dropped through these procedures so that
-- operators need no CREATE USER privilege: they get EXECUTE on them only. The procedures
-- run with the definer's rights (the administrator who loads this file).
DELIMITER //

CREATE OR REPLACE PROCEDURE robot_add(IN p_name VARCHAR(80), IN p_password VARCHAR(255), IN p_map VARCHAR(64),
                                      IN p_max_connections INT)
  MODIFIES SQL DATA SQL SECURITY DEFINER
  COMMENT 'creates a robot account with fleetmap_robot_role and its robots row'
BEGIN
  DECLARE v_map INT UNSIGNED DEFAULT NULL;
  DECLARE v_id INT UNSIGNED DEFAULT NULL;
  -- Binary comparison: under a case-insensitive collation 'R1' would pass (SPEC 5.1).
  IF p_name IS NULL OR NOT (p_name COLLATE utf8mb4_bin REGEXP '^[a-z0-9_-]{1,32}$') THEN
    SIGNAL SQLSTATE '45000' SET MESSAGE_TEXT = 'expected a robot name matching [a-z0-9_-]{1,32}';
  END IF;
  IF p_password IS NULL OR CHAR_LENGTH(p_password) < 12 THEN
    SIGNAL SQLSTATE '45000' SET MESSAGE_TEXT = 'expected a robot password of at least 12 characters';
  END IF;
  SELECT id INTO v_map FROM maps WHERE name = p_map;
  IF v_map IS NULL THEN
    SIGNAL SQLSTATE '45000' SET MESSAGE_TEXT = 'no map of that name';
  END IF;
  IF EXISTS (SELECT 1 FROM robots WHERE db_user = p_name AND removed_at IS NULL) THEN
    SIGNAL SQLSTATE '45000' SET MESSAGE_TEXT = 'a robot of that name exists';
  END IF;
  SET @fleetmap_sql = CONCAT('CREATE OR REPLACE USER ', QUOTE(p_name), '@''%'' IDENTIFIED BY ', QUOTE(p_password),
                             ' WITH MAX_USER_CONNECTIONS ', GREATEST(1, COALESCE(p_max_connections, 4)));
  PREPARE stmt FROM @fleetmap_sql; EXECUTE stmt; DEALLOCATE PREPARE stmt;
  SET @fleetmap_sql = CONCAT('GRANT fleetmap_robot_role TO ', QUOTE(p_name), '@''%''');
  PREPARE stmt FROM @fleetmap_sql; EXECUTE stmt; DEALLOCATE PREPARE stmt;
  SET @fleetmap_sql = CONCAT('SET DEFAULT ROLE fleetmap_robot_role FOR ', QUOTE(p_name), '@''%''');
  PREPARE stmt FROM @fleetmap_sql; EXECUTE stmt; DEALLOCATE PREPARE stmt;
  SET @fleetmap_sql = NULL;
  -- A robot added again keeps its id and its history.
  INSERT INTO robots (db_user, map_id) VALUES (p_name, v_map)
    ON DUPLICATE KEY UPDATE removed_at = NULL, map_id = v_map, state = 'offline', magic = NULL, session_at = NULL,
      ini_x = NULL, ini_y = NULL, ini_theta = NULL, x = NULL, y = NULL, theta = NULL, v = NULL, last_seen = NULL;
  -- The robot's sentinel in sa, exactly one (robot_remove deletes it with the mailbox): its
  -- locking reads of sa_mine end there, not on another robot's answers (SPEC 5.3, 10_schema.sql).
  -- A plain check, then a plain insert: INSERT ... SELECT would take shared gap locks on
  -- sa, and two operators adding robots whose names share a gap would deadlock.
  SELECT id INTO v_id FROM robots WHERE db_user = p_name;
  IF NOT EXISTS (SELECT 1 FROM sa WHERE db_user = p_name AND sentinel = 1) THEN
    INSERT INTO sa (robot_id, db_user, request_id, op, params, payload, created_at, sentinel)
      VALUES (v_id, p_name, NULL, 'End', '{}', NULL, SYSDATE(6), 1);
  END IF;
END//

CREATE OR REPLACE PROCEDURE robot_remove(IN p_name VARCHAR(80))
  MODIFIES SQL DATA SQL SECURITY DEFINER
  COMMENT 'drops a robot account, ends its connections, keeps its history'
BEGIN
  DECLARE v_done INT DEFAULT 0;
  DECLARE v_conn BIGINT;
  DECLARE cur CURSOR FOR SELECT id FROM information_schema.PROCESSLIST WHERE USER = p_name;
  DECLARE CONTINUE HANDLER FOR NOT FOUND SET v_done = 1;
  IF NOT EXISTS (SELECT 1 FROM robots WHERE db_user = p_name AND removed_at IS NULL) THEN
    SIGNAL SQLSTATE '45000' SET MESSAGE_TEXT = 'no robot of that name';
  END IF;
  SET @fleetmap_sql = CONCAT('DROP USER IF EXISTS ', QUOTE(p_name), '@''%''');
  PREPARE stmt FROM @fleetmap_sql; EXECUTE stmt; DEALLOCATE PREPARE stmt;
  OPEN cur;
  kill_loop: LOOP
    FETCH cur INTO v_conn;
    IF v_done THEN LEAVE kill_loop; END IF;
    SET @fleetmap_sql = CONCAT('KILL CONNECTION ', v_conn);
    PREPARE stmt FROM @fleetmap_sql; EXECUTE stmt; DEALLOCATE PREPARE stmt;
  END LOOP;
  CLOSE cur;
  SET @fleetmap_sql = NULL;
  UPDATE robots SET removed_at = SYSDATE(6), state = 'offline', magic = NULL, session_at = NULL WHERE db_user = p_name;
  -- Undelivered traffic is a mailbox, not history: an account created later under the same
  -- name must not read the old robot's answers. The sentinel goes too (robot_add makes a new one).
  DELETE FROM sa WHERE db_user = p_name;
  DELETE FROM rr WHERE db_user = p_name;
  UPDATE tasks t JOIN robots r ON r.id = t.robot_id SET t.state = 'failed', t.reason = 'robot removed'
    WHERE r.db_user = p_name AND t.state IN ('assigned', 'acknowledged', 'active');
END//

DELIMITER ;

GRANT EXECUTE ON PROCEDURE robot_add TO fleetmap_operator_role;
GRANT EXECUTE ON PROCEDURE robot_remove TO fleetmap_operator_role;
