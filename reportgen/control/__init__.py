"""The control work (контрольная работа) of the course manual (seed 001, §7–8): its 22 assignment
tables, the reconstructed schemes, the task file of a variant and the answer key of a variant."""
