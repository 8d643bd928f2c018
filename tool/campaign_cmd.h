// campaign_cmd.h — `handspring campaign` (campaign_cmd.c): many trials of a scenario, or a slice
// of them for GNU parallel and Slurm (scripts/campaign.sh), or the summary of merged rows.
#ifndef HS_CAMPAIGN_CMD_H
#define HS_CAMPAIGN_CMD_H

int hs_campaign_main(int argc, char **argv);

#endif
